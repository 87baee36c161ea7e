// The two-level scheme's driver (solvers/two_level.hpp).
#include "cartan/solvers/two_level.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "cartan/enum_names.hpp"
#include "cartan/errors.hpp"
#include "cartan/numerics/nonlinear_solve.hpp"

namespace cartan::solvers {

void solve_fixed_point(FixedPointSystem& system, const FixedPointOptions& options, const Eigen::VectorXd& v0_guess,
                       ResultCore& result) {
  const numerics::ResidualFunction counted = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    ++result.sweeps;
    return system.inner(x, r, options.analytic_jacobian ? jac : nullptr);
  };
  numerics::ResidualFunction inner = counted;
  if (!options.analytic_jacobian) {
    inner = numerics::with_forward_difference_jacobian(
        [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) { return counted(x, r, nullptr); }, 1e-7);
  }
  // Until a loop decides, the status is the initial NotConverged.
  const auto decided = [](Status s) { return s != Status::NotConverged; };
  result.status = Status::NotConverged;
  Eigen::VectorXd v0 = v0_guess;
  numerics::NonlinearSolveReport report;
  std::ostringstream history;
  bool recorded = false;  // a sweep of v0 with the current sequence was recorded (or failed to)
  for (int outer = 0; outer < options.max_outer; ++outer) {
    result.outer_iterations = outer + 1;
    // Steps 2-3: inner shooting for v0 with the current sequence.
    report = numerics::levenberg_marquardt(inner, v0, {.tolerance = options.inner_tolerance, .max_iterations = options.max_inner,
                                                       .monitor = options.monitor, .evaluations_stop = true});  // sweeps poll
    result.inner_iterations += report.iterations;
    v0 = report.x;
    recorded = false;
    if (report.status != Status::Converged) {
      result.status = report.status == Status::Interrupted ? Status::Interrupted : Status::InnerNotConverged;
      result.message = "two-level: inner shooting failed in outer iteration " + std::to_string(outer + 1) + ": " +
                       report.message + (system.failure().empty() ? "" : "; last failed sweep: " + system.failure());
      break;
    }
    // Step 4: the backward recursion (disc-aux).
    ++result.sweeps;
    const std::optional<double> change = system.update(v0);
    if (!change) {
      result.status = Status::NonFinite;
      result.message = "two-level: the sweep for the xi rates failed in outer iteration " + std::to_string(outer + 1) +
                       ": " + system.failure();
      break;
    }
    history << (outer ? ", " : "") << format_value(*change);
    result.residual_history.push_back(*change);
    if (!std::isfinite(*change)) {
      result.status = Status::NonFinite;
      break;
    }
    // Step 5: stop when the sequence no longer changes (relative to its size: shooting.hpp) and
    // the trajectory for it (step 6) still meets the end point: v0 was solved with the sequence
    // before the update, and where xi couples strongly (lambda (1 - lambda) far from 0, strong
    // anisotropy) a change below tol moved g_N by more (SE(2), inertia (1, 100, 1e4), lambda = 2:
    // 1.7e-8 "converged"). Else the next outer iteration solves v0 again with the new sequence.
    if (*change < options.tolerance * options.auxiliary_scale) {
      ++result.sweeps;
      recorded = true;
      if (!system.record(v0)) {
        result.status = Status::NonFinite;
        break;
      }
      if (result.terminal_error <= options.tolerance) {
        result.status = Status::Converged;
        break;
      }
    }
  }
  if (!decided(result.status)) result.status = Status::OuterNotConverged;
  // Step 6: the trajectory for the final sequence, unless step 5 recorded it.
  if (!recorded) {
    ++result.sweeps;
    if (!system.record(v0)) result.status = Status::NonFinite;
  }
  std::ostringstream message;
  message << "two-level: " << to_string(result.status) << " after " << result.outer_iterations << " outer and "
          << result.inner_iterations << " inner iterations, " << result.sweeps
          << " sweeps; outer changes max|xi_new - xi_old| = [" << history.str() << "]; terminal error "
          << format_value(result.terminal_error);
  if (!result.message.empty()) message << "; " << result.message;
  result.message = message.str();
}

}  // namespace cartan::solvers
