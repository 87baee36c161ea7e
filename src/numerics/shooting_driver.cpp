// The shooting driver (cartan/numerics/shooting_driver.hpp), compiled once for every kernel.
#include "cartan/numerics/shooting_driver.hpp"

#include <Eigen/QR>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "cartan/errors.hpp"
#include "cartan/monitor.hpp"

namespace cartan::numerics {

namespace {

/// The points whose sweeps recorded into the kernel's two buffers (the header's "Recording"): a
/// sweep never records into the buffer holding the point with the smaller |r|.
class RecordedSlots {
 public:
  /// The buffer for a sweep at x; it holds no point until `finish`.
  int start(const Eigen::VectorXd& x) {
    writing_ = 1 - best();
    Slot& slot = slots_[static_cast<std::size_t>(writing_)];
    slot.x.resize(0);
    slot.pending = x;
    return writing_;
  }
  /// The sweep begun by the last `start` completed, with residual norm `norm`.
  void finish(double norm) {
    Slot& slot = slots_[static_cast<std::size_t>(writing_)];
    slot.x = slot.pending;
    slot.norm = norm;
  }
  /// The buffer holding the point x, or -1.
  int find(const Eigen::VectorXd& x) const {
    for (int i = 0; i < 2; ++i) {
      const Slot& slot = slots_[static_cast<std::size_t>(i)];
      if (slot.x.size() == x.size() && slot.x == x) return i;
    }
    return -1;
  }

 private:
  struct Slot {
    Eigen::VectorXd x, pending;  ///< x: the point recorded (empty: none)
    double norm = std::numeric_limits<double>::infinity();
  };
  bool holds(int i) const { return slots_[static_cast<std::size_t>(i)].x.size() > 0; }
  /// The buffer with the smaller |r| among those holding a point (1 when neither does).
  int best() const { return holds(0) && (!holds(1) || slots_[0].norm <= slots_[1].norm) ? 0 : 1; }
  std::array<Slot, 2> slots_;
  int writing_ = 0;
};

/// Newton steps from a converged x (ShootingDriverOptions::aux_size) while |a_N / s| > aux_target:
/// a step is kept when the end point's residual stays within `tolerance` and |a_N| decreases.
void polish(const ResidualFunction& f, Eigen::Index nv, double aux_target, double tolerance, const SolveMonitor* monitor,
            NonlinearSolveReport& report) {
  constexpr int kSteps = 3;  // the auxiliary enters linearly: one step is the rule, three the bound
  const Eigen::Index na = report.residual.size() - nv;
  if (na < 1 || report.residual.tail(na).norm() <= aux_target) return;  // LM's own result is right already
  Eigen::VectorXd x = report.x, r, trial_r;
  Eigen::MatrixXd jacobian;
  for (int step = 0; step < kSteps; ++step) {
    if (monitor != nullptr && monitor->stop_requested()) return;
    ++report.evaluations;
    if (!f(x, r, &jacobian) || r.tail(na).norm() <= aux_target) break;
    const Eigen::VectorXd trial = x - jacobian.colPivHouseholderQr().solve(r);
    ++report.evaluations;
    if (!trial.allFinite() || !f(trial, trial_r, nullptr)) break;
    if (!(trial_r.head(nv).norm() <= tolerance && trial_r.tail(na).norm() < r.tail(na).norm())) break;
    x = trial;
    report.x = x;
    report.residual = trial_r;
    report.residual_norm = trial_r.norm();
  }
}

}  // namespace

std::string ShootingOutcome::summary() const {
  std::ostringstream out;
  out << report.message << ", " << sweeps << " sweeps";
  if (!failure.empty()) out << "; last failed sweep: " << failure;
  if (stopped_before_a_sweep) out << "; stopped before a sweep completed: no trajectory";
  return out.str();
}

ShootingOutcome shoot(ShootingKernel& kernel, const ShootingDriverOptions& options, const Eigen::VectorXd& y0) {
  const Eigen::Index size = y0.size(), nv = options.velocity_size, na = size - nv;
  if (nv < 1 || na < 1) {
    throw_invalid("shoot", "velocity_size", std::to_string(nv),
                  "must leave at least one unknown to each of v0 and a0 (" + std::to_string(size) + " unknowns)");
  }
  require_finite(options.horizon, "shoot", "horizon");
  require_finite(options.aux_scale, "shoot", "aux_scale");
  if (!(options.horizon > 0)) throw_invalid("shoot", "horizon", format_value(options.horizon), "must be positive");
  if (!(options.aux_scale > 0)) throw_invalid("shoot", "aux_scale", format_value(options.aux_scale), "must be positive");
  if (!(options.aux_size >= 0) || !std::isfinite(options.aux_size)) {
    throw_invalid("shoot", "aux_size", format_value(options.aux_size), "must be finite and non-negative (0: none)");
  }
  require_finite(y0, "shoot", "y0");
  const double T = options.horizon, s = options.aux_scale;
  const SolveMonitor* monitor = options.solver.monitor;
  ShootingOutcome outcome;
  RecordedSlots slots;
  // x = (T v0, a0 / s) and back; residual rows (r_q, a_N / s); Jacobian columns by (1 / T, s).
  const auto unknowns = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd y(size);
    y << x.head(nv) / T, x.tail(na) * s;
    return y;
  };
  const auto evaluate = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, bool record) {
    const int slot = record ? slots.start(x) : -1;
    ++outcome.sweeps;
    // After a stop comes the result (a quarter of a plain sweep covers it) where this sweep
    // records, else a recording sweep. The deadline applies that much earlier
    // (SolveMonitor::reserve_after_stop).
    const double share = SolveMonitor::sweeps_after_stop(record, jacobian != nullptr, 0.25);
    const auto begin = std::chrono::steady_clock::now();
    // A stop during this sweep leaves nothing to do where it records (the best point's trajectory
    // is at hand or there is none), else the recording sweep: what its polls project.
    const SweepEnd end = kernel.sweep(unknowns(x), r, jacobian, slot, record ? 0.0 : share, outcome.failure);
    if (end != SweepEnd::Failed && monitor != nullptr) {  // a sweep that ran to T times the next ones
      monitor->reserve_after_stop(
          std::chrono::duration_cast<std::chrono::nanoseconds>((std::chrono::steady_clock::now() - begin) * share));
    }
    if (end != SweepEnd::Done) return false;
    r.tail(na) /= s;
    if (record) slots.finish(r.norm());
    if (jacobian != nullptr) {
      jacobian->bottomRows(na) /= s;
      jacobian->leftCols(nv) /= T;
      jacobian->rightCols(na) *= s;
    }
    return true;
  };
  const ResidualFunction f =
      options.analytic_jacobian
          ? ResidualFunction([&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian) {
              return evaluate(x, r, jacobian, true);
            })
          : with_forward_difference_jacobian(
                [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) { return evaluate(x, r, nullptr, false); },
                options.solver.fd_step);
  Eigen::VectorXd x0(size);
  x0 << y0.head(nv) * T, y0.tail(na) / s;
  outcome.report = levenberg_marquardt(f, x0, options.solver);
  if (outcome.report.status == Status::Converged && options.aux_size > 0 && options.aux_size < s) {
    polish(f, nv, options.solver.tolerance * options.aux_size / s, options.solver.tolerance, monitor, outcome.report);
  }
  outcome.y = unknowns(outcome.report.x);
  const int slot = options.analytic_jacobian ? slots.find(outcome.report.x) : -1;
  outcome.stopped_before_a_sweep =
      slot < 0 && options.analytic_jacobian && outcome.report.status == Status::Interrupted;
  outcome.status = outcome.report.status;
  if (outcome.stopped_before_a_sweep) return outcome;  // no sweep after a stop
  if (slot < 0) ++outcome.sweeps;
  outcome.has_trajectory = kernel.record_result(outcome.y, slot);
  if (!outcome.has_trajectory) outcome.status = Status::NonFinite;
  return outcome;
}

}  // namespace cartan::numerics
