#pragma once
// The report on a solution assembled once, for every kernel (src/verify/assemble.cpp): the
// kernel's checks measure the figures (kernels/lie_group/verify_checks.hpp on a Lie group, kernels/manifold/verify.hpp on a
// manifold: their arithmetic differs, docs/design/one-core.md D19), and this turns them into
// checks with thresholds C a^q rho^p (verify/verdict.hpp) and words.

#include <optional>
#include <string>

#include "cartan/status.hpp"
#include "cartan/verify/figures.hpp"
#include "cartan/verify/verdict.hpp"

namespace cartan::verify {

/// What a kernel's checks measured on one solution, and how it names each figure.
struct Figures {
  double resolution = 0;     ///< rho = h omega
  double amplification = 1;  ///< a, the lambda factor (the Lie-group kernel's; 1 on a general connection)
  double boundary = 0;       ///< against tol
  std::string boundary_note;
  double legendre = 0;  ///< against kLegendreThreshold
  std::string legendre_note;
  double energy = 0;
  /// C of the energy threshold C a^(p+1) rho^p: kEnergyConstant where the drift is bounded in
  /// time (Lie groups), a bound growing with the horizon elsewhere (kernels/manifold/verify.hpp).
  double energy_constant = kEnergyConstant;
  std::string energy_note;
  Residual residual;
  std::string residual_equations;  ///< what the residual is of: "eq:reduced-system", "the local form"
  std::optional<double> stationarity;  ///< empty: not applicable, for the reason in stationarity_note
  /// The samples' roundoff against their steps, relative (figures.hpp step_roundoff): stationarity's
  /// floor, and the residual's at least (v and mu of a path at rest are roundoff too).
  double step_roundoff = 0;
  std::string stationarity_note;
};

/// The report: a failing `converged` check unless status is converged, then boundary, legendre,
/// energy, residual, stationarity. Thresholds assume order min(order, 2) (collocation's samples are
/// checked at second order) and are at most 1 (every figure is relative).
Report assemble(const Figures& figures, int order, double tol, Status status);

}  // namespace cartan::verify
