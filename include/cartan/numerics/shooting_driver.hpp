#pragma once
// One shooting driver for every kernel: the Lie-group scheme (methods/lie_group/shooting.hpp) and the
// scheme of any manifold with a connection (methods/manifold/shooting.hpp) sweep; the decisions are made
// here, once, in compiled code (src/numerics/shooting_driver.cpp).
//
// The unknowns y = (v0, a0) are the initial velocity (n_v numbers) and the auxiliary's initial
// value (xi0 on a Lie group, Xi0 in general); a sweep from y gives the terminal residual
// r = (r_q, a_N): how far q_N is from qT, and the auxiliary at T, which must vanish. Levenberg–
// Marquardt solves r(y) = 0 in dimensionless form, so that one tolerance means the same at every
// horizon: unknowns x = (T v0, a0 / s) and residual (r_q, a_N / s), s the auxiliary's scale
// (methods/lie_group/shooting.hpp's header comment). The Jacobian comes from the kernel's
// tangent-linear sweep (analytic) or from forward differences.
//
// Recording. With the analytic Jacobian every sweep records its nodes, into one of two buffers the
// kernel keeps, never into the one holding the best point so far; the result (Levenberg–Marquardt's
// best point) then has its trajectory at hand, even when a stop (time limit, cancellation) cut the
// last sweep short, and a stop before any sweep of it completed leaves no trajectory rather than a
// sweep after the stop. With differences, the result's point is swept once more, recording.

#include <Eigen/Core>
#include <string>

#include "cartan/numerics/nonlinear_solve.hpp"

namespace cartan::numerics {

/// How a kernel's sweep ended.
enum class SweepEnd {
  Failed,     ///< stopped short: a non-finite state, a failed callback, a stop request
  Undefined,  ///< ran to T, but the residual is not defined there (q_N on the cut locus of qT)
  Done,       ///< ran to T: r (and the Jacobian) filled
};

/// What the driver asks of a scheme. Unknowns and residuals are in the problem's own units.
class ShootingKernel {
 public:
  virtual ~ShootingKernel() = default;
  /// One sweep from y = (v0, a0): r = (r_q, a_N) and, when `jacobian` is not null, dr/dy (a
  /// tangent-linear sweep). The nodes go to buffer `slot` (0 or 1), or nowhere for slot < 0.
  /// `after_stop`: the work after a stop, in sweeps of this kind, for the sweep's polls to project
  /// until a sweep has been timed (SolveMonitor::stop_pending_at). Unless Done, `failure` says why.
  virtual SweepEnd sweep(const Eigen::VectorXd& y, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, int slot,
                         double after_stop, std::string& failure) = 0;
  /// Makes the result's trajectory that of y: buffer `slot`, where a completed sweep of y recorded,
  /// or (slot < 0) a recording sweep of y. False when that sweep failed (then no trajectory).
  virtual bool record_result(const Eigen::VectorXd& y, int slot) = 0;
};

struct ShootingDriverOptions {
  int velocity_size = 0;    ///< n_v: y = (v0, a0) with v0 the first n_v unknowns
  double horizon = 1;       ///< T, the scale of v0
  double aux_scale = 1;     ///< s, the scale of a0 and a_N
  /// u, the auxiliary's own size where it is below s (0: none). aux_scale floors the speed at 1/T
  /// (principle/scales.hpp), so Levenberg–Marquardt meets |a_N| <= tol s only; for a shorter path
  /// Newton steps from its result then bring |a_N| to tol u (the auxiliary right to its own size),
  /// each kept only if the end point stays within tol.
  double aux_size = 0;
  bool analytic_jacobian = true;
  NonlinearSolveOptions solver;  ///< Levenberg–Marquardt's, on the dimensionless problem
};

struct ShootingOutcome {
  NonlinearSolveReport report;  ///< Levenberg–Marquardt's, on the dimensionless unknowns
  Eigen::VectorXd y;            ///< the result's (v0, a0), in the problem's units
  /// The report's status; NonFinite when the result's recording sweep failed (no trajectory).
  Status status = Status::MaxIterations;
  bool has_trajectory = false;
  bool stopped_before_a_sweep = false;  ///< stopped before a sweep of y completed: no trajectory
  int sweeps = 0;                       ///< every sweep, tangent-linear and recording ones included
  std::string failure;                  ///< why the last failed sweep failed (empty: none did)

  /// "<Levenberg–Marquardt's message>, <k> sweeps[; last failed sweep: ...][; stopped before a
  /// sweep completed: no trajectory]": what every shooting message ends with.
  std::string summary() const;
};

/// Shooting from y0 (the problem's units). Throws std::invalid_argument for bad options or a
/// non-finite y0; numerical trouble is the outcome's status.
ShootingOutcome shoot(ShootingKernel& kernel, const ShootingDriverOptions& options, const Eigen::VectorXd& y0);

}  // namespace cartan::numerics
