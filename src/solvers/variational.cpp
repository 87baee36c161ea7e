// The variational method's Newton iteration (solvers/variational.hpp).
#include "cartan/solvers/variational.hpp"

#include <Eigen/LU>
#include <chrono>
#include <sstream>
#include <utility>

#include "cartan/errors.hpp"

namespace cartan::solvers {

PathNewtonOutcome newton_on_path(PathSystem& system, const PathNewtonOptions& options, std::vector<double>& history) {
  PathNewtonOutcome out;
  Eigen::VectorXd gradient, trial_gradient;
  Eigen::MatrixXd hessian;
  std::ostringstream why;
  Status status = Status::MaxIterations;
  int iteration = 0;
  if (!system.gradient(gradient)) {
    status = Status::NonFinite;
    why << "the gradient at the start is not finite";
  } else if (system.unknowns() == 0) {
    status = Status::Converged;  // N = 1: no interior node, the path is the step from g0 to gT
  }
  auto iteration_begin = std::chrono::steady_clock::now();
  for (; status == Status::MaxIterations && iteration < options.max_iterations; ++iteration) {
    const auto now = std::chrono::steady_clock::now();
    const auto last_iteration = now - iteration_begin;  // the next one is begun only if it can end in time
    iteration_begin = now;
    if (options.monitor && options.monitor->stop_requested_before(last_iteration)) {
      status = Status::Interrupted;
      break;
    }
    if (!system.hessian(gradient, hessian)) {
      status = Status::NonFinite;
      why << "the Hessian is not finite at iteration " << iteration;
      break;
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(hessian);
    const Eigen::VectorXd delta = -lu.solve(gradient);
    if (!delta.allFinite()) {
      status = Status::SingularJacobian;
      why << "the Hessian is singular at iteration " << iteration;
      break;
    }
    // Damping by the natural monotonicity test: a step s delta is accepted when the simplified
    // correction at the trial is at most (1 - s / 4) of delta.
    double s = 1;
    Eigen::VectorXd correction;
    for (;; s /= 2) {
      if (s < 1.0 / 1024) break;
      if (!system.trial(delta, s, trial_gradient)) continue;
      correction = -lu.solve(trial_gradient);
      if (correction.norm() <= (1 - s / 4) * delta.norm()) {
        system.accept();
        std::swap(gradient, trial_gradient);
        break;
      }
    }
    if (s < 1.0 / 1024) {
      status = Status::Stalled;
      why << "no damped step passed the monotonicity test at iteration " << iteration << " (|delta| = "
          << format_value(delta.cwiseAbs().maxCoeff()) << ")";
      break;
    }
    const double remaining = correction.cwiseAbs().maxCoeff();
    history.push_back(remaining);
    if (options.monitor) options.monitor->report(iteration, remaining);
    if (remaining <= options.tolerance) status = Status::Converged;
  }
  out.status = status;
  out.iterations = iteration;
  out.why = why.str();
  return out;
}

}  // namespace cartan::solvers
