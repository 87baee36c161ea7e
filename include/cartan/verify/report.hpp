#pragma once
// The verdict on a solution of the transported-velocity BVP: the checks of verify/checks.hpp,
// each with its figure, its threshold and PASS / FAIL / N/A. `cartan verify` (CLI) and
// `cartan.verify` (Python) print this report; C++ users call verify_solution on any result of
// any model. docs/verify.md explains each check and where its threshold comes from.

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cartan/enum_names.hpp"
#include "cartan/errors.hpp"
#include "cartan/transported/shooting.hpp"
#include "cartan/transported/solution.hpp"
#include "cartan/verify/checks.hpp"

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

/// The report on a failed result that kept no trajectory: the failing `converged` check alone.
inline Report unchecked_failure(Status status) {
  Report report;
  report.checks.push_back(convergence_check(status));
  report.checks.push_back({"data", 0, 0, false, "not checked: the result has no trajectory"});
  return report;
}

/// Runs every check on `x`, a solution of `problem` (its Lagrangian, lambda, T, g0, gT; N is not
/// used: x may have any number of samples) computed to tolerance `tol` by a method of the given
/// order (1, 2, or 4 for collocation). A `status` other than converged adds a failing
/// `converged` check (the data are then a best iterate). Throws std::invalid_argument for an
/// invalid trajectory (TransportedTrajectory::validate, with mu), order or tol.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
Report verify_trajectory(const transported::TransportedProblem<G, L>& problem, transported::TransportedTrajectory<G> x, int order, double tol,
                         Status status = Status::Converged) {
  if (order < 1) throw_invalid("verify", "order", std::to_string(order), "must be at least 1");
  if (!(tol > 0) || !std::isfinite(tol)) throw_invalid("verify", "tol", format_value(tol), "must be positive and finite");
  x.validate(problem.T, "verify", true, 1e-9);
  const TrajectoryChecks<G, L> checks(problem.lagrangian, problem.lambda, problem.T, std::move(x));
  Report report;
  report.order = std::min(order, 2);
  report.resolution = checks.max_step() * checks.frequency();
  report.amplification = checks.amplification();
  // At most 1: every figure is relative, and a threshold above 100 % says nothing. It also keeps
  // thresholds finite when absurd data (found by fuzzing: an xi of 1e215) make a overflow.
  auto threshold = [&](double constant, int extra_power) {
    const double lambda_factor = std::pow(report.amplification, report.order + extra_power);
    const double value =
        discretisation_threshold(constant * lambda_factor, report.resolution, report.order) + threshold_floor(tol);
    return std::isfinite(value) ? std::min(value, 1.0) : 1.0;
  };
  if (status != Status::Converged) report.checks.push_back(convergence_check(status));
  // Shooting stops at |xi_N| / xi_scale <= tol (shooting.hpp), so xi_N may exceed tol where
  // xi_scale > 1: measure it in units of max(1, xi_scale), never looser than absolute.
  const double xi_unit = std::max(1.0, transported::xi_scale(problem));
  report.checks.push_back({"boundary", checks.boundary_error(problem.g0, problem.gT, xi_unit), tol, true,
                           "max(|log(g0^-1 g_0)|, |log(gT^-1 g_N)|, |xi_N| / max(1, xi_scale)) against tol"});
  report.checks.push_back({"legendre", checks.legendre_residual(), kLegendreThreshold, true,
                           "max |mu - dl/dv(g, v)|, relative"});
  report.checks.push_back({"energy", checks.energy_drift(), threshold(kEnergyConstant, 1), true,
                           "max |E - E(0)| / max |E|, E = mu.v - l (conserved for every lambda when l does not depend "
                           "on t)"});
  const Residual residual = checks.equation_residual();
  report.checks.push_back({"residual", residual.relative, threshold(kResidualConstant, 0), true,
                           "eq:reduced-system by finite differences, worst: " + residual.equation + " at t = " +
                               Report::format(residual.t)});
  const bool uniform = is_uniform(checks.trajectory().t);
  report.checks.push_back({"stationarity", uniform ? checks.action_stationarity(kVariations, kVariationSeed) : 0,
                           threshold(kActionConstant, 0), uniform,
                           uniform ? "max |dS| / (size of its terms) over " + std::to_string(kVariations) +
                                         " random endpoint-fixed variations"
                                   : "t is not uniform (collocation on its own mesh): sample it uniformly "
                                     "(samples = M)"});
  return report;
}

/// verify_trajectory on a solver's result: its trajectory, order and status. A result without a
/// trajectory (a failure that kept no iterate) gets the failing `converged` check alone.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
Report verify_solution(const transported::TransportedProblem<G, L>& problem, const transported::TransportedSolution<G>& solution, double tol) {
  if (solution.trajectory.t.empty() && !solution.converged()) return unchecked_failure(solution.status);
  return verify_trajectory(problem, solution.trajectory, solution.order, tol, solution.status);
}

}  // namespace cartan::verify
