#pragma once
// The report of check_lagrangian (check_lagrangian.hpp): one entry per check of a model's
// callbacks, a verdict, and a printable text that names each failing callback and the size of
// its discrepancy, and the options of the seeded samples. Not templated (compiled in
// src/mechanics/check_report.cpp).

#include <cstdint>
#include <string>
#include <vector>

#include "cartan/groups/side.hpp"

namespace cartan::mechanics {

/// The seeded samples of a check (check_lagrangian.hpp on a group, manifold_check_lagrangian.hpp on a
/// manifold).
struct CheckLagrangianOptions {
  int samples = 8;               ///< how many seeded samples
  std::uint32_t seed = 20261122u;
  /// t uniform in [0, scale]; g = exp(w) (on a manifold q = step(q, E w)) and v with every
  /// coordinate uniform in [-scale, scale].
  double scale = 1.0;
  /// How the model trivialises group_gradient (lagrangian.hpp): Left for left-reduced models,
  /// Right for right-reduced ones (e.g. SpatialRigidBody). Not used on a manifold.
  groups::Side side = groups::Side::Left;
};

/// One check of one callback over all samples.
struct CallbackCheck {
  std::string callback;   ///< the callback checked: "momentum", "group_gradient", "velocity", "hessian.momentum_v", ...
  std::string reference;  ///< what it is compared with ("central differences of value along v", ...)
  bool checked = true;    ///< false: nothing to check (e.g. no analytic hessian); then ok
  bool ok = true;
  /// The largest relative discrepancy over the samples, |callback - reference|_inf / max(|callback|_inf,
  /// |reference|_inf, floor) (check_lagrangian.hpp); +inf for a non-finite value or an exception.
  double discrepancy = 0;
  /// The relative error of the reference itself at that sample (the finite-difference error
  /// estimate; 0 for the exact inverse relations of `velocity`).
  double reference_error = 0;
  double threshold = 0;  ///< ok when discrepancy <= threshold
  int sample = -1;       ///< index of the sample of the largest discrepancy (-1: none)
  std::string at;        ///< that sample, "t = ..., g = ..., v = ..."
  std::string note;      ///< "lagrangian.value returned a non-finite value", "threw: ...", or empty
};

struct CheckReport {
  std::vector<CallbackCheck> checks;
  int samples = 0;
  std::string title = "check_lagrangian";  ///< the first word of text()

  bool ok() const;
  /// The callbacks whose check failed, in order.
  std::vector<std::string> failing() const;
  /// "check_lagrangian: FAIL (group_gradient), 8 samples" and one line per check: the callback, PASS/FAIL
  /// ("-" when not checked), the discrepancy, the reference's own error and the threshold, and
  /// for a failure the sample where the discrepancy is largest.
  std::string text() const;
};

}  // namespace cartan::mechanics
