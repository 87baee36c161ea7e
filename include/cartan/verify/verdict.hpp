#pragma once
// The verdict on a solution: checks, each with its figure, its threshold and PASS / FAIL / N/A,
// and the thresholds' constants (docs/verify.md). Both verifiers return it: verify_trajectory
// (kernels/lie_group/verify.hpp, on the transported problem) and verify_general (kernels/manifold/verify.hpp); the
// CLI and Python print it. Light: what a unit that only reads or prints a report needs.

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cartan/enum_names.hpp"
#include "cartan/status.hpp"

namespace cartan::verify {

struct Check {
  std::string name;
  double figure = 0;     ///< the measured (dimensionless or absolute) size
  double threshold = 0;  ///< PASS when figure <= threshold
  bool applicable = true;
  std::string note;      ///< what the figure is, or why the check does not apply

  bool passed() const { return !applicable || figure <= threshold; }
  std::string verdict() const { return !applicable ? "N/A" : passed() ? "PASS" : "FAIL"; }
};

struct Report {
  double resolution = 0;     ///< rho = h omega: the largest step times the motion's frequency
  int order = 0;             ///< p, the order the thresholds assume (min(solution order, 2))
  double amplification = 1;  ///< a, the lambda factor of the thresholds (TrajectoryChecks::amplification)
  std::vector<Check> checks;

  bool passed() const {
    return !checks.empty() && std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.passed(); });
  }

  /// One line per check (name, figure, threshold, verdict, note), then "VERDICT: PASS|FAIL".
  std::string text() const {
    std::ostringstream out;
    out << "resolution h*omega = " << format(resolution) << ", thresholds of order " << order;
    if (amplification > 1) out << ", lambda factor a = " << format(amplification);
    out << "\n";
    for (const auto& c : checks) {
      char line[64];
      std::snprintf(line, sizeof line, "%-13s %-10s <= %-10s %-4s  ", c.name.c_str(),
                    c.applicable ? format(c.figure).c_str() : "-", c.applicable ? format(c.threshold).c_str() : "-",
                    c.verdict().c_str());
      out << line << c.note << "\n";
    }
    out << "VERDICT: " << (passed() ? "PASS" : "FAIL") << "\n";
    return out.str();
  }

  static std::string format(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", x);
    return buffer;
  }
};

// Thresholds (docs/verify.md). rho = h omega is the angle one step sweeps (TrajectoryChecks::
// frequency), p = min(order, 2): the order-1 scheme is O(h), the order-2 scheme O(h^2), and
// collocation output (order 4, a cubic interpolant) is checked through the same second-order
// finite differences, so O(h^2) too. Each threshold is C a^q rho^p; C is about 7-10 times the
// largest figure / rho^p measured on honest results at lambda in [0, 1] (where a = 1;
// bench/README.md, "verify thresholds"), a the lambda factor (TrajectoryChecks::amplification):
//  * residual and stationarity, q = p: the local error of an order-p step is O((a rho)^(p+1)),
//    and both figures are relative to terms that grow like a, so they are O((a rho)^p).
//  * energy, q = p + 1: one explicit Euler step changes E = 1/2 mu.M^-1 mu by v.(h mu') +
//    1/2 h^2 |mu'|^2_{M^-1}; the first term is the exact (u.zeta) change because v.ad*_v(.) = 0,
//    the second is the error, and the coadjoint part of mu' is a times omega |mu|: a^2 rho per
//    step relative to E (order 1, measured: the drift / rho at lambda = 2, -1 is 8 times that at
//    0, 1 on the free body, with a^2 = 11). An order-p step's energy error is a^(p+1) rho^(p+1).
//    The error is measured bounded in time (no secular growth), so no factor T.
// A wrong lambda, model or sample moves a figure by O(1) (tests/cli/test_verify.py).
inline constexpr double kResidualConstant = 1.5;
inline constexpr double kActionConstant = 1.0;
inline constexpr double kEnergyConstant = 3.0;
/// The largest threshold a discretisation check may have and still decide: every figure is
/// relative, and above 1 the solution's own discretisation error may be as large as the figure of a
/// curve that solves another problem (O(1): a wrong sign, factor or term, tests/cli/test_verify.py).
/// Such a check is unresolved: not applicable at this resolution, saying so and naming the threshold
/// it would need (it was capped at 1 and passed an energy drift of 0.649 of a wrong Lagrangian); a
/// report whose discretisation checks are all unresolved or not applicable fails (check
/// "resolution"): nothing in it tells a solution from another curve.
inline constexpr double kCoarsestThreshold = 1.0;
/// mu = dl/dv is imposed exactly by every method (natural Lagrangians: mu = I v).
inline constexpr double kLegendreThreshold = 1e-9;
/// Variations of the action check, and their seed (deterministic).
inline constexpr int kVariations = 6;
inline constexpr unsigned kVariationSeed = 20261122u;

/// Floor of the discretisation thresholds: the solver's own tolerance (collocation's residual
/// tolerance is relative) and rounding in the differences.
inline double threshold_floor(double tol) { return 10 * tol + 1e-10; }

/// The check a result that did not converge always fails.
inline Check convergence_check(Status status) {
  return {"converged", status == Status::Converged ? 0.0 : 1.0, 0, true,
          "status = " + std::string(to_string(status)) +
              (status == Status::Converged ? ""
                                           : ": the solver did not converge; the data are its best iterate, not a "
                                             "solution")};
}

/// The report on a failed result whose data cannot be checked (it kept no trajectory, or its
/// samples are none: a diverged iterate's points off the manifold, non-finite values): the failing
/// `converged` check, and `why` nothing else was checked.
inline Report unchecked_failure(Status status, const std::string& why = "the result has no trajectory") {
  Report report;
  report.checks.push_back(convergence_check(status));
  report.checks.push_back({"data", 0, 0, false, "not checked: " + why});
  return report;
}

}  // namespace cartan::verify
