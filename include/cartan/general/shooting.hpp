#pragma once
// Shooting for the general problem (problem.hpp): solve for (v0, Xi0) with the terminal conditions
// (difference(qT, q_N), Xi_N) = 0 by the library's Levenberg–Marquardt solver, with the
// dimensionless scaling of transported/shooting.hpp: unknowns (T v0, Xi0 / s), residual
// (r_q, Xi_N / s), s = T |v_ref| |mu_ref| with v_ref the geodesic-guess velocity. The Jacobian is
// tangent-linear (tangent.hpp: one sweep carries the m + m^2 variations) or, with
// analytic_jacobian = false, by forward differences (1 + m + m^2 sweeps).

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "cartan/general/scheme.hpp"
#include "cartan/general/tangent.hpp"
#include "cartan/numerics/nonlinear_solve.hpp"
#include "cartan/numerics/recorded_points.hpp"
#include "cartan/status.hpp"
#include "cartan/transported/method.hpp"
#include "cartan/transported/shooting.hpp"
#include "cartan/transported/solution.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M>
struct GeneralSolution {
  Status status = Status::NotConverged;
  std::string message;
  transported::Method method = transported::Method::Shooting;
  std::string branch;
  int order = 1;
  /// Every node of the requested problem's discrete solution (at a failure: of the best iterate).
  GeneralTrajectory<M> trajectory;
  manifolds::ComponentsOf<M> v0 = manifolds::ComponentsOf<M>::Zero();
  manifolds::ComponentMatrixOf<M> Xi0 = manifolds::ComponentMatrixOf<M>::Zero();
  double terminal_error = 0;  ///< separation(qT, q_N): |difference(qT, q_N)| where it is a logarithm
  double xi_terminal = 0;     ///< |Xi_N|
  int iterations = 0;
  int sweeps = 0;
  std::vector<double> residual_history;
  double solve_time_s = 0;
  std::optional<transported::CollocationReport> collocation;  ///< method collocation: mesh and residual

  bool converged() const { return status == Status::Converged; }
};

/// The Lie-group shooting's options (order, tolerance, max_iterations, analytic_jacobian: the
/// tangent-linear sweep of tangent.hpp, no_progress_window, monitor), so that the continuation
/// path (transported/continuation.hpp) drives both problem families.
using GeneralShootingOptions = transported::ShootingOptions;

/// The geodesic guess: difference(q0, qT) / T in the components of the initial frame.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
manifolds::ComponentsOf<M> geodesic_guess(const GeneralProblem<M, L>& problem) {
  return manifolds::dual_frame<M>(problem.initial_frame()) * problem.manifold.difference(problem.q0, problem.qT) /
         problem.T;
}

/// The size of Xi on this problem: T |v_ref| |mu_ref| (transported/shooting.hpp's xi_scale).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
double xi_scale(const GeneralProblem<M, L>& problem) {
  manifolds::ComponentsOf<M> v = geodesic_guess(problem);
  if (!(v.norm() > 0)) v = manifolds::ComponentsOf<M>::Unit(0) / problem.T;
  const double scale = problem.T * v.norm() * problem.lagrangian.momentum(0, problem.q0, v).norm();
  return std::isfinite(scale) && scale > std::numeric_limits<double>::min() ? scale : 1.0;
}

/// Runs the N steps from (v0, Xi0); returns the last node, or nothing (with `failure` set) when
/// the state became non-finite, a callback failed or `monitor` has a stop pending (polled every
/// SolveMonitor::kStepsBetweenPolls steps). ModelError passes through. With `tangent`,
/// the variations run along (tangent.hpp) and `jacobian` (m + m^2 square) receives
/// d (terminal_residual, Xi_N reshaped) / d (v0, Xi0 reshaped).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
std::optional<GeneralNode<M>> general_sweep(const GeneralScheme<M, L>& scheme, const manifolds::ComponentsOf<M>& v0,
                                            const manifolds::ComponentMatrixOf<M>& Xi0, std::string& failure,
                                            GeneralTrajectory<M>* trajectory = nullptr,
                                            const GeneralSchemeTangent<M, L>* tangent = nullptr,
                                            Eigen::MatrixXd* jacobian = nullptr, const SolveMonitor* monitor = nullptr) {
  constexpr int m = M::kDim;
  const auto begin = std::chrono::steady_clock::now();
  try {
    GeneralNode<M> node = scheme.initial(v0, Xi0), next;
    GeneralNodeTangent<M> dnode, dnext;
    if (tangent) dnode = tangent->initial(node);
    if (trajectory) trajectory->clear(), trajectory->push(node);
    for (int k = 0; k < scheme.problem().N; ++k) {
      // Until a sweep is timed, what follows a stop is projected: a recording sweep (a tangent-linear
      // sweep costs about 3 plain ones or more), or nothing where the sweeps record themselves.
      const double after_stop = trajectory ? 0.0 : tangent ? 1.0 / 3 : 1.0;
      if (SolveMonitor::stop_pending_at(monitor, k, scheme.problem().N, begin, after_stop)) {
        failure = SolveMonitor::stopped_message(k);
        return std::nullopt;
      }
      tangent ? tangent->step(node, dnode, next, dnext) : scheme.step(node, next);
      if (!next.q.allFinite() || !next.frame.allFinite() || !next.mu.allFinite() || !next.Xi.allFinite() ||
          !next.v.allFinite() ||
          (tangent && !(dnext.q.allFinite() && dnext.frame.allFinite() && dnext.mu.allFinite() && dnext.Xi.allFinite()))) {
        failure = "non-finite state at step " + std::to_string(k + 1);
        return std::nullopt;
      }
      node = next;
      if (tangent) dnode = dnext;
      if (trajectory) trajectory->push(node);
    }
    if (tangent && jacobian) {
      jacobian->resize(m + m * m, m + m * m);
      *jacobian << tangent->terminal_residual_tangent(node, dnode), dnode.Xi;
    }
    return node;
  } catch (const ModelError&) {
    throw;
  } catch (const std::exception& e) {
    failure = e.what();
    return std::nullopt;
  }
}

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve_general_shooting(const GeneralProblem<M, L>& problem, const GeneralShootingOptions& options,
                                          const manifolds::ComponentsOf<M>& v0_guess,
                                          const manifolds::ComponentMatrixOf<M>& Xi0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_general_shooting", "v0_guess");
  require_finite(Xi0_guess, "solve_general_shooting", "Xi0_guess");
  constexpr int m = M::kDim;
  const auto start = std::chrono::steady_clock::now();
  const GeneralScheme<M, L> scheme(problem, options.order);
  const GeneralSchemeTangent<M, L> tangent(scheme);
  GeneralSolution<M> solution;
  solution.order = static_cast<int>(options.order);
  const double T = problem.T, s = xi_scale(problem);
  std::string failure;
  using Xi = manifolds::ComponentMatrixOf<M>;
  auto unpack = [&](const Eigen::VectorXd& x) {
    return std::pair<manifolds::ComponentsOf<M>, Xi>(x.head<m>() / T, Xi(x.tail<m * m>().reshaped(m, m) * s));
  };
  // Unknowns (T v0, Xi0 / s) and residual rows (r_q, Xi_N / s): the Jacobian's columns scale by
  // (1 / T, s) and its Xi rows by 1 / s.
  Eigen::VectorXd scaling(m + m * m);
  scaling << Eigen::VectorXd::Constant(m, 1 / T), Eigen::VectorXd::Constant(m * m, s);
  // As in transported/shooting.hpp: the analytic path records every sweep, so that the result's
  // point needs no sweep of its own, even after a stop cut a sweep short.
  numerics::RecordedPoints<GeneralTrajectory<M>> points;
  auto residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian) {
    const auto [v0, Xi0] = unpack(x);
    ++solution.sweeps;
    GeneralTrajectory<M>* trajectory = options.analytic_jacobian ? points.start(x) : nullptr;
    const auto begin = std::chrono::steady_clock::now();
    const auto last = general_sweep(scheme, v0, Xi0, failure, trajectory, jacobian ? &tangent : nullptr, jacobian,
                                    options.monitor);
    if (!last) return false;
    // After a stop: the result, or a recording sweep when none was recorded (a tangent-linear
    // sweep costs about 3 plain ones or more).
    if (options.monitor) {
      const double share = (trajectory ? 0.25 : 1.0) / (jacobian ? 3 : 1);
      options.monitor->reserve_after_stop(
          std::chrono::duration_cast<std::chrono::nanoseconds>((std::chrono::steady_clock::now() - begin) * share));
    }
    if (!scheme.terminal_residual_defined(last->q)) {  // the cut locus of qT: r_q would be meaningless
      failure = "q_N = " + format_value(last->q) + " is where difference(qT, .) is not defined (the cut locus of qT " +
                "or outside the domain)";
      return false;
    }
    r.resize(m + m * m);
    r << scheme.terminal_residual(*last), last->Xi.reshaped() / s;
    if (trajectory) points.finish(r.norm());
    if (jacobian) {
      *jacobian = *jacobian * scaling.asDiagonal();
      jacobian->bottomRows(m * m) /= s;
    }
    return true;
  };
  auto residual_only = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) { return residual(x, r, nullptr); };
  Eigen::VectorXd x0(m + m * m);
  x0 << v0_guess * T, Xi0_guess.reshaped() / s;
  numerics::NonlinearSolveOptions lm;
  lm.tolerance = options.tolerance;
  lm.max_iterations = options.max_iterations;
  lm.no_progress_window = options.no_progress_window;
  lm.max_initial_residual = options.max_initial_residual;
  lm.monitor = options.monitor;
  const numerics::NonlinearSolveReport report =
      numerics::levenberg_marquardt(options.analytic_jacobian
                                        ? numerics::ResidualFunction(residual)
                                        : numerics::with_forward_difference_jacobian(residual_only, lm.fd_step),
                                    x0, lm);
  solution.iterations = report.iterations;
  solution.residual_history = report.residual_history;
  const auto [v0, Xi0] = unpack(report.x);
  std::optional<GeneralNode<M>> last;
  GeneralTrajectory<M>* recorded = points.find(report.x);
  // Stopped before a sweep of the result's point completed: no trajectory, not a sweep after the stop.
  const bool unrecorded_stop = !recorded && report.status == Status::Interrupted && options.analytic_jacobian;
  if (recorded) {
    solution.trajectory = std::move(*recorded);
    last = solution.trajectory.back();
  } else if (!unrecorded_stop) {
    ++solution.sweeps;
    std::string record_failure;
    last = general_sweep(scheme, v0, Xi0, record_failure, &solution.trajectory);
  }
  if (last) {
    solution.v0 = v0;
    solution.Xi0 = Xi0;
    solution.terminal_error = scheme.terminal_error(last->q);
    solution.xi_terminal = last->Xi.norm();
    solution.status = report.status;
    if (solution.converged() && !(solution.terminal_error <= options.tolerance)) {  // never a wrong "converged"
      solution.status = Status::NotConverged;
    }
  } else {
    solution.trajectory = {};
    solution.status = unrecorded_stop ? report.status : Status::NonFinite;
  }
  std::ostringstream message;
  message << "general shooting (" << (options.analytic_jacobian ? "tangent-linear" : "finite-difference")
          << " Jacobian, Xi scale " << format_value(s)
          << (scheme.uses_constant_components() ? ", constant frame components" : "") << "): " << report.message
          << ", " << solution.sweeps << " sweeps";
  if (!failure.empty()) message << "; last failed sweep: " << failure;
  if (unrecorded_stop) message << "; stopped before a sweep completed: no trajectory";
  if (report.status == Status::Converged && !solution.converged()) {
    message << "; but q_N is " << format_value(solution.terminal_error) << " from qT: not converged";
  }
  solution.message = message.str();
  solution.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return solution;
}

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve_general_shooting(const GeneralProblem<M, L>& problem, const GeneralShootingOptions& options = {}) {
  problem.validate();
  return solve_general_shooting(problem, options, geodesic_guess(problem), manifolds::ComponentMatrixOf<M>::Zero());
}

}  // namespace cartan::general
