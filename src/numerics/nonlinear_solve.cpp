#include "cartan/numerics/nonlinear_solve.hpp"

#include <sstream>

#include "cartan/errors.hpp"

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

bool evaluate(const ResidualFunction& f, const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd& jac,
              NonlinearSolveReport& report) {
  ++report.evaluations;
  return f(x, r, &jac) && r.allFinite() && jac.allFinite();
}

void finish(NonlinearSolveReport& report, Status status, const std::string& why) {
  report.status = status;
  std::ostringstream out;
  out << to_string(status) << " after " << report.iterations << " iterations and " << report.evaluations
      << " evaluations, |r| = " << format_value(report.residual_norm);
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
  if (!evaluate(f, report.x, r, jac, report)) {
    report.residual = r;
    report.residual_norm = r.size() ? r.norm() : std::nan("");
    finish(report, Status::NonFinite, "at the initial guess");
    return report;
  }
  report.residual = r;
  report.residual_norm = r.norm();
  report.residual_history.push_back(report.residual_norm);
  Eigen::MatrixXd a = jac.transpose() * jac;
  Eigen::VectorXd grad = jac.transpose() * r;
  double mu = options.initial_damping * std::max(a.diagonal().maxCoeff(), 1e-300);
  double nu = 2;
  Eigen::VectorXd r_new;
  Eigen::MatrixXd jac_new;
  // best[i]: the best |r| after i iterations (the no-progress test compares across a window).
  std::vector<double> best{report.residual_norm};
  while (true) {
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
      if (options.monitor->stop_requested()) {
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
    Eigen::MatrixXd damped = a;
    damped.diagonal().array() += mu;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(damped);
    if (ldlt.info() != Eigen::Success) {
      finish(report, Status::SingularJacobian, "damped normal equations not solvable");
      return report;
    }
    const Eigen::VectorXd step = ldlt.solve(-grad);
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
    if (evaluate(f, x_new, r_new, jac_new, report)) {
      const double rho = (r.squaredNorm() - r_new.squaredNorm()) / std::max(predicted, 1e-300);
      if (rho > 0) {
        accepted = true;
        report.x = x_new;
        r = r_new;
        jac = jac_new;
        a = jac.transpose() * jac;
        grad = jac.transpose() * r;
        report.residual = r;
        report.residual_norm = r.norm();
        report.residual_history.push_back(report.residual_norm);
        mu *= std::max(1.0 / 3.0, 1 - std::pow(2 * rho - 1, 3));
        nu = 2;
      }
    }
    best.push_back(std::min(best.back(), report.residual_norm));
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
