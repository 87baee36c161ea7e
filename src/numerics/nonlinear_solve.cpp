#include "cartan/numerics/nonlinear_solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "cartan/errors.hpp"
#include "cartan/numerics/dense_lu.hpp"

namespace cartan::numerics {

ResidualFunction with_forward_difference_jacobian(std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd&)> f,
                                                  double fd_step) {
  return [f = std::move(f), fd_step](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    if (!f(x, r)) return false;
    if (jac == nullptr) return true;
    jac->resize(r.size(), x.size());
    Eigen::VectorXd xp = x, rp;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const double step = fd_step * std::max(1.0, std::abs(x[i]));
      xp[i] = x[i] + step;
      if (!f(xp, rp)) return false;
      jac->col(i) = (rp - r) / step;
      xp[i] = x[i];
    }
    return true;
  };
}

namespace {

/// Evaluates r (and J when jac is set) at x; false when the evaluation failed or is not finite.
bool evaluate(const ResidualFunction& f, const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac,
              NonlinearSolveReport& report) {
  ++report.evaluations;
  return f(x, r, jac) && r.allFinite() && (jac == nullptr || jac->allFinite());
}

/// What the last accepted step predicts. In Newton's quadratic phase (|r| fell by more than 10)
/// r_next ~ K r^2 with K = |r| / |r_prev|^2; before it, linearly, r_next ~ |r| rate. A chord
/// step from the next point with the present Jacobian then gives about 2 K r r_next (the error
/// of the stale Jacobian, K |r|, times the residual it corrects).
struct Prediction {
  double next = std::numeric_limits<double>::infinity();
  double after_chord = std::numeric_limits<double>::infinity();
};
Prediction predict(const std::vector<double>& history) {
  if (history.size() < 2) return {};
  const double now = history.back(), before = history[history.size() - 2];
  if (!(now < before)) return {};
  const double rate = now / before;
  if (!(rate < 0.1)) return {now * rate, std::numeric_limits<double>::infinity()};
  const double next = now * rate * rate;
  return {next, 2 * (rate / before) * now * next};
}

/// From this many unknowns the normal matrix J^T J is formed in column chunks and the damped
/// normal equations are solved by the blocked LU (numerics/dense_lu.hpp), both polling the
/// monitor between pieces of work: at 1152 unknowns (128 segments of SO(3)) J^T J and Eigen's LDLT
/// took 0.1-0.3 s past a time limit. Below it, one product and Eigen's LDLT, as before (the golden
/// cases keep their results bit for bit).
constexpr Eigen::Index kPolledFrom = 512;

/// a = J^T J; false when `stop` (called between chunks of about BlockedLU::kFlopsBetweenPolls
/// flops, from kPolledFrom unknowns) asks to stop.
bool normal_matrix(const Eigen::MatrixXd& jac, Eigen::MatrixXd& a, const std::function<bool()>& stop) {
  const Eigen::Index n = jac.cols();
  if (n < kPolledFrom) {
    a.noalias() = jac.transpose() * jac;
    return true;
  }
  a.resize(n, n);
  const double per_column = 2.0 * static_cast<double>(jac.rows()) * static_cast<double>(n);
  const Eigen::Index chunk = std::max<Eigen::Index>(1, static_cast<Eigen::Index>(BlockedLU::kFlopsBetweenPolls / per_column));
  for (Eigen::Index first = 0; first < n; first += chunk) {
    if (stop()) return false;
    const Eigen::Index width = std::min(chunk, n - first);
    a.middleCols(first, width).noalias() = jac.transpose() * jac.middleCols(first, width);
  }
  return true;
}

/// The damped normal equations' solver: Eigen's LDLT below kPolledFrom unknowns, the blocked LU
/// polling `stop` from it on (J^T J + mu D is symmetric positive definite: partial pivoting is
/// stable on it).
class DampedSolver {
 public:
  enum class Outcome { Solved, Singular, Stopped };
  Outcome factorize(const Eigen::MatrixXd& a, double mu, const std::function<bool()>& stop) {
    blocked_used_ = a.rows() >= kPolledFrom;
    if (!blocked_used_) {
      Eigen::MatrixXd damped = a;
      damped.diagonal().array() += mu;
      ldlt_.compute(damped);
      return ldlt_.info() == Eigen::Success ? Outcome::Solved : Outcome::Singular;
    }
    blocked_.matrix() = a;
    blocked_.matrix().diagonal().array() += mu;
    switch (blocked_.factorize(stop)) {
      case BlockedLU::Outcome::Factorized: return Outcome::Solved;
      case BlockedLU::Outcome::Singular: return Outcome::Singular;
      case BlockedLU::Outcome::Stopped: return Outcome::Stopped;
    }
    return Outcome::Singular;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return blocked_used_ ? blocked_.solve(b) : ldlt_.solve(b); }

 private:
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  BlockedLU blocked_;
  bool blocked_used_ = false;
};

void finish(NonlinearSolveReport& report, Status status, const std::string& why) {
  report.status = status;
  std::ostringstream out;
  out << to_string(status) << " after " << report.iterations << " iterations and " << report.evaluations
      << " evaluations, |r| = " << (std::isnan(report.residual_norm) ? std::string("undefined") : format_value(report.residual_norm));
  if (!why.empty()) out << " (" << why << ")";
  report.message = out.str();
}

}  // namespace

void NonlinearSolveOptions::validate() const {
  const auto positive = [](double value, const char* name) {
    require_finite(value, "NonlinearSolveOptions", name);
    if (!(value > 0)) throw_invalid("NonlinearSolveOptions", name, format_value(value), "must be positive");
  };
  positive(tolerance, "tolerance");
  positive(initial_damping, "initial_damping");
  positive(step_tolerance, "step_tolerance");
  positive(fd_step, "fd_step");
  if (!(max_initial_residual > 0)) {  // +inf (no limit) allowed; NaN is not
    throw_invalid("NonlinearSolveOptions", "max_initial_residual", format_value(max_initial_residual), "must be positive");
  }
  if (max_iterations < 1) {
    throw_invalid("NonlinearSolveOptions", "max_iterations", std::to_string(max_iterations), "must be at least 1");
  }
  if (no_progress_window < 0) {
    throw_invalid("NonlinearSolveOptions", "no_progress_window", std::to_string(no_progress_window),
                  "must be non-negative");
  }
}

NonlinearSolveReport levenberg_marquardt(const ResidualFunction& f, const Eigen::VectorXd& x0,
                                         const NonlinearSolveOptions& options) {
  options.validate();
  require_finite(x0, "levenberg_marquardt", "x0");
  if (!f) throw std::invalid_argument("levenberg_marquardt: f is empty (no residual function)");
  NonlinearSolveReport report;
  report.x = x0;
  Eigen::VectorXd r;
  Eigen::MatrixXd jac;
  // A sweep stopped by the monitor (time limit, cancellation) fails like a non-finite one.
  const auto stop = [&] { return options.monitor != nullptr && options.monitor->stop_requested(); };
  if (!evaluate(f, report.x, r, &jac, report)) {
    report.residual = r;
    report.residual_norm = std::nan("");  // the failed evaluation left r undefined (it read |r| = 0)
    if (stop()) {
      finish(report, Status::Interrupted, "stop requested");
    } else {
      finish(report, Status::NonFinite, "at the initial guess");
    }
    return report;
  }
  report.residual = r;
  report.residual_norm = r.norm();
  report.residual_history.push_back(report.residual_norm);
  if (report.residual_norm > options.max_initial_residual) {
    finish(report, Status::NoProgress, "|r| at the start above max_initial_residual = " +
                                           format_value(options.max_initial_residual));
    return report;
  }
  // Polled inside the normal matrix and the damped solve from kPolledFrom unknowns.
  const std::function<bool()> poll = [&options] { return SolveMonitor::poll(options.monitor); };
  const auto interrupted = [&report] {
    finish(report, Status::Interrupted, "stop requested");
    return report;
  };
  Eigen::MatrixXd a;
  if (!normal_matrix(jac, a, poll)) return interrupted();
  Eigen::VectorXd grad = jac.transpose() * r;
  DampedSolver damped;
  double mu = options.initial_damping * std::max(a.diagonal().maxCoeff(), 1e-300);
  double nu = 2;
  Eigen::VectorXd r_new;
  Eigen::MatrixXd jac_new;
  bool stale_jacobian = false;  // jac belongs to an earlier point than report.x (a chord step)
  bool rejected_before = false;  // the last trial was rejected
  // The Jacobian (and the residual again) at the current point, after a residual-only evaluation.
  const auto fresh_jacobian = [&] {
    if (!evaluate(f, report.x, r, &jac, report)) {
      if (stop()) {
        finish(report, Status::Interrupted, "stop requested");
      } else {
        finish(report, Status::NonFinite, "the Jacobian at an accepted point failed");
      }
      return false;
    }
    if (!normal_matrix(jac, a, poll)) {
      finish(report, Status::Interrupted, "stop requested");
      return false;
    }
    grad = jac.transpose() * r;
    stale_jacobian = false;
    return true;
  };
  // best[i]: the best |r| after i iterations (the no-progress test compares across a window).
  std::vector<double> best{report.residual_norm};
  auto iteration_begin = std::chrono::steady_clock::now();
  while (true) {
    const auto now = std::chrono::steady_clock::now();
    const auto last_iteration = now - iteration_begin;  // without evaluations_stop, the next one is begun only if it can end in time
    iteration_begin = now;
    if (report.residual_norm <= options.tolerance) {
      finish(report, Status::Converged, "");
      return report;
    }
    if (report.iterations >= options.max_iterations) {
      finish(report, Status::MaxIterations, "");
      return report;
    }
    if (options.monitor != nullptr) {
      options.monitor->report(report.iterations, report.residual_norm);
      const bool stopping = options.evaluations_stop ? options.monitor->stop_requested()
                                                     : options.monitor->stop_requested_before(last_iteration);
      if (stopping) {
        finish(report, Status::Interrupted, "stop requested");
        return report;
      }
    }
    const int window = options.no_progress_window;
    if (window > 0 && report.iterations >= window &&
        best.back() > 0.5 * best[static_cast<std::size_t>(report.iterations - window)]) {
      finish(report, Status::NoProgress,
             "|r| did not halve in the last " + std::to_string(window) + " iterations");
      return report;
    }
    ++report.iterations;
    const DampedSolver::Outcome factorized = damped.factorize(a, mu, poll);
    if (factorized == DampedSolver::Outcome::Stopped) return interrupted();
    if (factorized == DampedSolver::Outcome::Singular) {
      finish(report, Status::SingularJacobian, "damped normal equations not solvable");
      return report;
    }
    const Eigen::VectorXd step = damped.solve(-grad);
    if (!step.allFinite()) {
      finish(report, Status::SingularJacobian, "non-finite step");
      return report;
    }
    if (step.norm() <= options.step_tolerance * (report.x.norm() + options.step_tolerance)) {
      finish(report, Status::Stalled, "step below relative tolerance");
      return report;
    }
    const Eigen::VectorXd x_new = report.x + step;
    const double predicted = step.dot(mu * step - grad);
    bool accepted = false;
    // A Jacobian is asked for at the trial point unless the point is predicted to converge, or to
    // converge after one chord step (the present Jacobian reused): where a tangent-linear sweep
    // costs several plain ones, the residual alone is then evaluated. A wrong prediction costs
    // the Jacobian at the accepted point (one residual more), or a fresh one after a rejection.
    // The chord step itself is one of these: a trial from a stale Jacobian is evaluated alone; so
    // is a trial after a rejected one (far from a root, where the model fails, rejections come
    // in runs).
    const Prediction prediction = stale_jacobian ? Prediction{} : predict(report.residual_history);
    const bool with_jacobian = !stale_jacobian && !rejected_before &&
                               !(prediction.next <= options.tolerance || prediction.after_chord <= options.tolerance);
    if (evaluate(f, x_new, r_new, with_jacobian ? &jac_new : nullptr, report)) {
      const double rho = (r.squaredNorm() - r_new.squaredNorm()) / std::max(predicted, 1e-300);
      if (rho > 0) {
        accepted = true;
        report.x = x_new;
        r = r_new;
        report.residual = r;
        report.residual_norm = r.norm();
        report.residual_history.push_back(report.residual_norm);
        mu *= std::max(1.0 / 3.0, 1 - std::pow(2 * rho - 1, 3));
        nu = 2;
        if (with_jacobian) {
          jac = jac_new;
          if (!normal_matrix(jac, a, poll)) return interrupted();
          stale_jacobian = false;
        } else if (report.residual_norm > options.tolerance) {
          if (prediction.after_chord <= options.tolerance && !stale_jacobian) {
            stale_jacobian = true;  // one chord step: the Jacobian of the previous point
          } else if (!fresh_jacobian()) {
            return report;
          }
        }
        grad = jac.transpose() * r;
      }
    }
    best.push_back(std::min(best.back(), report.residual_norm));
    if (!accepted && stale_jacobian && !fresh_jacobian()) return report;
    rejected_before = !accepted;
    if (!accepted) {
      mu *= nu;
      nu *= 2;
      if (!std::isfinite(mu)) {
        finish(report, Status::Stalled, "damping overflowed");
        return report;
      }
    }
  }
}

}  // namespace cartan::numerics
