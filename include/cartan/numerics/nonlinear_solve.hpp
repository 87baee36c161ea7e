#pragma once
// A small Levenberg–Marquardt solver for square or overdetermined systems r(x) = 0, used by the
// shooting solvers. Written here rather than taken from Eigen's unsupported MINPACK port because
// the solvers need an absolute stopping rule on |r| (the terminal error the paper asks for),
// a Jacobian computed in the same forward sweep as the residual, and a count of evaluations and
// residual history for diagnostics.
//
// Damping follows Nielsen's rule: mu <- mu max(1/3, 1 - (2 rho - 1)^3) on success, mu <- nu mu,
// nu <- 2 nu on failure, with rho the ratio of actual to predicted reduction.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "cartan/monitor.hpp"
#include "cartan/status.hpp"

namespace cartan::numerics {

// Outcomes (cartan/status.hpp): Converged (|r| <= tolerance), MaxIterations, Stalled (steps
// negligible while |r| > tolerance: a local minimum of |r|), NonFinite (residual or Jacobian
// NaN/inf), SingularJacobian (damped normal equations not solvable), NoProgress (best |r| not
// halved within no_progress_window iterations, or |r| at x0 above max_initial_residual),
// Interrupted (the monitor asked to stop).

struct NonlinearSolveOptions {
  double tolerance = 1e-12;      ///< stop when |r|_2 <= tolerance
  int max_iterations = 200;      ///< Jacobian evaluations (accepted + rejected steps)
  double initial_damping = 1e-8; ///< tau: mu_0 = tau max diag(J^T J); small = Gauss–Newton-like
  double step_tolerance = 1e-15; ///< relative step size below which the solve has stalled
  double fd_step = 1e-7;         ///< relative step of forward-difference Jacobians
  /// > 0: give up (Status::NoProgress) once the best |r| has not halved over this many
  /// iterations; a start outside Newton's basin is then abandoned early, while a converging
  /// solve (which gains far more than a factor 2 per few iterations) finishes.
  int no_progress_window = 0;
  /// Give up (Status::NoProgress) at once when |r| at x0 exceeds this: a continuation stage whose
  /// predictor is this far off has taken too large an increment, and is cheaper to retry with a
  /// smaller one than to solve (continuation.hpp). Infinite (the default): no limit.
  double max_initial_residual = std::numeric_limits<double>::infinity();
  /// Progress reports (one per iteration) and stop requests (Status::Interrupted); may be null.
  const SolveMonitor* monitor = nullptr;
  /// True when f itself polls the monitor and fails promptly once a stop is pending (the shooting
  /// sweeps poll it about every millisecond, SolveMonitor::stop_pending_at): an iteration is then begun up
  /// to the deadline, and a stop cuts it short with the last accepted point, so that the solve
  /// ends at its time limit rather than up to an iteration before it. False: an iteration is begun
  /// only if it can end in time (its length foreseen from the last one's).
  bool evaluations_stop = false;

  /// Throws std::invalid_argument naming the first value that is not finite and positive.
  void validate() const;
};

struct NonlinearSolveReport {
  Status status = Status::MaxIterations;
  Eigen::VectorXd x;
  Eigen::VectorXd residual;
  double residual_norm = 0;
  int iterations = 0;   ///< LM iterations (trial steps)
  int evaluations = 0;  ///< calls of the residual function
  std::vector<double> residual_history;  ///< |r| at each accepted point
  std::string message;
};

/// Residual function: fills r (and J when jacobian != nullptr) at x. Returns false to signal a
/// failed evaluation (treated like a non-finite residual: the step is rejected).
using ResidualFunction =
    std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian)>;

/// Wraps a residual-only function f(x, r) -> bool with a forward-difference Jacobian
/// (one extra evaluation per unknown, step fd_step * max(1, |x_i|)) - the paper's choice.
ResidualFunction with_forward_difference_jacobian(
    std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd&)> f, double fd_step);

/// Levenberg–Marquardt from x0. Throws std::invalid_argument for bad options, a non-finite x0 or
/// an empty f; never throws for numerical trouble: the report says what happened.
NonlinearSolveReport levenberg_marquardt(const ResidualFunction& f, const Eigen::VectorXd& x0,
                                         const NonlinearSolveOptions& options = {});

}  // namespace cartan::numerics
