// The variational method's Newton iteration (solvers/variational.hpp).
#include "cartan/solvers/variational.hpp"

#include <Eigen/LU>
#include <sstream>
#include <utility>

#include "cartan/errors.hpp"
#include "cartan/numerics/dense_lu.hpp"

namespace cartan::solvers {

namespace {

/// Eigen's PartialPivLU below this many unknowns (at most 0.15 s; the golden variational case,
/// 897 unknowns, keeps its result bit for bit), the blocked LU that polls the monitor from it on
/// (numerics/dense_lu.hpp; at N = 2000 on SO(3), 5997 unknowns, Eigen's takes 13 s unstoppable).
constexpr Eigen::Index kBlockedFrom = 1024;

/// The Hessian, written in place by the kernel, and its LU: in place from kBlockedFrom unknowns
/// (no copy of a matrix of up to hundreds of MB), in Eigen's copy below.
class HessianLU {
 public:
  Eigen::MatrixXd& matrix() { return blocked_.matrix(); }
  /// Factorises matrix(); Stopped when the monitor polls a stop (from kBlockedFrom unknowns).
  numerics::BlockedLU::Outcome factorize(const SolveMonitor* monitor) {
    blocked_used_ = matrix().rows() >= kBlockedFrom;
    if (blocked_used_) return blocked_.factorize([monitor] { return SolveMonitor::poll(monitor); });
    small_.compute(matrix());
    return numerics::BlockedLU::Outcome::Factorized;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return blocked_used_ ? blocked_.solve(b) : small_.solve(b); }

 private:
  numerics::BlockedLU blocked_;
  Eigen::PartialPivLU<Eigen::MatrixXd> small_;
  bool blocked_used_ = false;
};

}  // namespace

PathNewtonOutcome newton_on_path(PathSystem& system, const PathNewtonOptions& options, std::vector<double>& history) {
  PathNewtonOutcome out;
  Eigen::VectorXd gradient, trial_gradient;
  HessianLU lu;
  std::ostringstream why;
  Status status = Status::MaxIterations;
  int iteration = 0;
  if (!system.gradient(gradient)) {
    status = Status::NonFinite;
    why << "the gradient at the start is not finite";
  } else if (system.unknowns() == 0) {
    status = Status::Converged;  // N = 1: no interior node, the path is the step from g0 to gT
  }
  // The Hessian, its LU and the damping trials poll the monitor: a stop ends the iteration where
  // it is, with the last accepted path.
  const auto stopped = [&] { return options.monitor != nullptr && options.monitor->stop_requested(); };
  for (; status == Status::MaxIterations && iteration < options.max_iterations; ++iteration) {
    if (stopped()) {
      status = Status::Interrupted;
      break;
    }
    if (!system.hessian(gradient, lu.matrix())) {
      status = stopped() ? Status::Interrupted : Status::NonFinite;
      if (status == Status::NonFinite) why << "the Hessian is not finite at iteration " << iteration;
      break;
    }
    const numerics::BlockedLU::Outcome factorized = lu.factorize(options.monitor);
    if (factorized == numerics::BlockedLU::Outcome::Stopped) {
      status = Status::Interrupted;
      break;
    }
    const Eigen::VectorXd delta =
        factorized == numerics::BlockedLU::Outcome::Singular ? Eigen::VectorXd() : Eigen::VectorXd(-lu.solve(gradient));
    if (delta.size() == 0 || !delta.allFinite()) {
      status = Status::SingularJacobian;
      why << "the Hessian is singular at iteration " << iteration;
      break;
    }
    // Damping by the natural monotonicity test: a step s delta is accepted when the simplified
    // correction at the trial is at most (1 - s / 4) of delta.
    double s = 1;
    bool accepted = false, interrupted = false;
    Eigen::VectorXd correction;
    for (; s >= 1.0 / 1024; s /= 2) {
      if (SolveMonitor::poll(options.monitor)) {
        interrupted = true;
        break;
      }
      if (!system.trial(delta, s, trial_gradient)) continue;
      correction = -lu.solve(trial_gradient);
      // Monotone, or already within tol (as collocation's acceptance): at the exact solution
      // (g0 = gT away from e, gradient 3.8e-30) delta and the correction are both roundoff, and the
      // monotonicity test alone reported "stalled".
      if (correction.norm() <= (1 - s / 4) * delta.norm() || correction.cwiseAbs().maxCoeff() <= options.tolerance) {
        system.accept();
        std::swap(gradient, trial_gradient);
        accepted = true;
        break;
      }
    }
    if (interrupted) {
      status = Status::Interrupted;
      break;
    }
    if (!accepted) {
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
