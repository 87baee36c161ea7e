#pragma once
// Augmented shooting (beyond the paper): integrate xi forward from an unknown xi0 and solve for
// (v0, xi0) with the terminal conditions (log(gT^{-1} g_N), xi_N) = 0 in one Levenberg–Marquardt
// problem. Its solution satisfies the same discrete equations as the fixed point of the paper's
// two-level scheme (xi_k from the backward recursion with xi_N = 0), without the outer loop.
// The Jacobian is analytic (a tangent-linear sweep, one sweep per evaluation) or by forward
// differences (1 + 2n sweeps).
//
// Scale. The unknowns and residual are made dimensionless so that the same tolerance means the
// same at every horizon: v0 in units of 1/T, xi in units of the curvature integral's size
// xi_scale = T |v_ref| |mu_ref| (v_ref the geodesic velocity, mu_ref its momentum at g0; for a
// kinetic Lagrangian the problem at horizon cT is then the same problem). The convergence test
// is |(log(gT^{-1} g_N), xi_N / xi_scale)| <= tolerance: radians, and a relative xi.

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "cartan/numerics/nonlinear_solve.hpp"
#include "cartan/numerics/recorded_points.hpp"
#include "cartan/transported/solution.hpp"
#include "cartan/transported/sweep.hpp"

namespace cartan::transported {

struct ShootingOptions {
  SchemeOrder order = SchemeOrder::First;
  double tolerance = 1e-10;     ///< on |(log(gT^{-1} g_N), xi_N / xi_scale)| (dimensionless)
  int max_iterations = 100;     ///< Levenberg–Marquardt iterations
  bool analytic_jacobian = true;
  int no_progress_window = 0;   ///< > 0: abandon when |r| has not halved in this many iterations
  /// Abandon at once when the scaled |r| of the guess exceeds this (continuation stages).
  double max_initial_residual = std::numeric_limits<double>::infinity();
  const SolveMonitor* monitor = nullptr;  ///< progress and stop requests; may be null

  void validate() const {
    require_finite(tolerance, "ShootingOptions", "tolerance");
    if (!(tolerance > 0)) throw_invalid("ShootingOptions", "tolerance", format_value(tolerance), "must be positive");
    if (max_iterations < 1) {
      throw_invalid("ShootingOptions", "max_iterations", std::to_string(max_iterations), "must be at least 1");
    }
    if (!(max_initial_residual > 0)) {
      throw_invalid("ShootingOptions", "max_initial_residual", format_value(max_initial_residual), "must be positive");
    }
  }
};

/// The paper's initial guess: the body velocity of the geodesic from g0 to gT, log(g0^{-1} gT)/T.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
groups::TangentOf<G> geodesic_guess(const TransportedProblem<G, L>& problem) {
  return groups::log_between<G>(problem.g0, problem.gT) / problem.T;
}

/// The size of xi on this problem (see the header comment): T |v_ref| |mu_ref|, with v_ref the
/// geodesic velocity (or 1/T along the first axis when g0 = gT); at least the smallest normal.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
double xi_scale(const TransportedProblem<G, L>& problem) {
  groups::TangentOf<G> v = geodesic_guess(problem);
  if (!(v.norm() > 0)) v = groups::TangentOf<G>::Unit(0) / problem.T;
  const double scale = problem.T * v.norm() * problem.lagrangian.momentum(0, problem.g0, v).norm();
  return std::isfinite(scale) && scale > std::numeric_limits<double>::min() ? scale : 1.0;
}

namespace detail {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Final recorded sweep shared by the solvers: fills trajectory and terminal figures. With
/// `recorded` (the trajectory of a sweep from the same v0 and xi0), takes it instead of sweeping.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
bool record_solution(const TransportedScheme<G, L>& scheme, const groups::TangentOf<G>& v0, const groups::CovectorOf<G>& xi0,
                     const std::vector<groups::CovectorOf<G>>* given_xi, TransportedSolution<G>& solution,
                     TransportedTrajectory<G>* recorded = nullptr) {
  if (recorded != nullptr) {
    solution.trajectory = std::move(*recorded);
  } else {
    SweepOutput<G, L> out;
    out.trajectory = &solution.trajectory;
    ++solution.sweeps;
    if (!forward_sweep(scheme, v0, xi0, given_xi, 0, out)) {
      solution.trajectory = {};  // never a partial trajectory
      return false;
    }
  }
  const TransportedTrajectory<G>& tr = solution.trajectory;
  solution.v0 = v0;
  solution.xi0 = tr.xi.front();
  solution.terminal_error = groups::log_between<G>(scheme.problem().gT, tr.g.back()).norm();  // terminal_residual
  solution.xi_terminal = tr.xi.back().norm();
  return true;
}

}  // namespace detail

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_shooting(const TransportedProblem<G, L>& problem, const ShootingOptions& options,
                                      const groups::TangentOf<G>& v0_guess, const groups::CovectorOf<G>& xi0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_shooting", "v0_guess");
  require_finite(xi0_guess, "solve_shooting", "xi0_guess");
  constexpr int n = G::kDim;
  const auto start = std::chrono::steady_clock::now();
  const TransportedScheme<G, L> scheme(problem, options.order);
  TransportedSolution<G> solution;
  solution.method = Method::Shooting;
  solution.order = static_cast<int>(options.order);
  std::string failure;
  // Dimensionless unknowns x = (T v0, xi0 / s) and residual (r_g, xi_N / s) (header comment).
  const double T = problem.T, s = xi_scale(problem);

  auto unpack = [&](const Eigen::VectorXd& x) {
    return std::pair<groups::TangentOf<G>, groups::CovectorOf<G>>(x.head<n>() / T, x.tail<n>() * s);
  };
  // The analytic path records every sweep (numerics/recorded_points.hpp): the result's point, the
  // last accepted one, then needs no sweep of its own, even after a stop cut a sweep short.
  numerics::RecordedPoints<TransportedTrajectory<G>> points;
  // After a stop comes the result: nothing more where the sweep recorded (a stopped result has no
  // action, solve.hpp), a recording sweep where it did not (the finite-difference path).
  auto reserve = [&](std::chrono::steady_clock::time_point begin, double share) {
    if (options.monitor) {
      options.monitor->reserve_after_stop(
          std::chrono::duration_cast<std::chrono::nanoseconds>((std::chrono::steady_clock::now() - begin) * share));
    }
  };
  auto residual_only = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, TransportedTrajectory<G>* trajectory = nullptr) {
    const auto [v0, xi0] = unpack(x);
    SweepOutput<G, L> out;
    out.trajectory = trajectory;
    out.monitor = options.monitor;
    ++solution.sweeps;
    const auto begin = std::chrono::steady_clock::now();
    if (!forward_sweep(scheme, v0, xi0, nullptr, 0, out)) {
      failure = out.failure;
      return false;
    }
    reserve(begin, trajectory ? 0.0 : 1.0);
    r.resize(2 * n);
    r << scheme.terminal_residual(out.last), out.last.xi / s;
    return true;
  };
  numerics::ResidualFunction f;
  if (options.analytic_jacobian) {
    f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
      TransportedTrajectory<G>* trajectory = points.start(x);
      if (jac == nullptr) {
        if (!residual_only(x, r, trajectory)) return false;
        points.finish(r.norm());
        return true;
      }
      const auto [v0, xi0] = unpack(x);
      SweepOutput<G, L> out;
      out.monitor = options.monitor;
      out.trajectory = trajectory;
      ++solution.sweeps;
      const auto begin = std::chrono::steady_clock::now();
      if (!forward_sweep(scheme, v0, xi0, nullptr, 2 * n, out)) {
        failure = out.failure;
        return false;
      }
      reserve(begin, 0.0);  // it recorded: nothing follows a stop
      const groups::TangentOf<G> rg = scheme.terminal_residual(out.last);
      r.resize(2 * n);
      r << rg, out.last.xi / s;
      points.finish(r.norm());
      // Chain rule for the scaled unknowns: columns for v0 / T and xi0 s; rows of xi_N / s.
      jac->resize(2 * n, 2 * n);
      jac->topRows(n) = scheme.terminal_residual_tangent(rg, *out.tangent);
      jac->bottomRows(n) = out.tangent->xi / s;
      jac->leftCols(n) /= T;
      jac->rightCols(n) *= s;
      return true;
    };
  } else {
    f = numerics::with_forward_difference_jacobian(
        [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) { return residual_only(x, r); }, 1e-7);
  }
  Eigen::VectorXd x0(2 * n);
  x0 << v0_guess * T, xi0_guess / s;
  const numerics::NonlinearSolveReport report =
      numerics::levenberg_marquardt(f, x0, {.tolerance = options.tolerance, .max_iterations = options.max_iterations,
                                  .no_progress_window = options.no_progress_window,
                                  .max_initial_residual = options.max_initial_residual, .monitor = options.monitor});
  solution.inner_iterations = report.iterations;
  solution.residual_history = report.residual_history;
  const auto [v0, xi0] = unpack(report.x);
  TransportedTrajectory<G>* recorded = points.find(report.x);
  // Stopped before a sweep of the result's point completed: no trajectory (as after a non-finite
  // sweep), not a sweep after the stop.
  const bool unrecorded_stop = !recorded && report.status == Status::Interrupted && options.analytic_jacobian;
  const bool ok = !unrecorded_stop && detail::record_solution(scheme, v0, xi0, nullptr, solution, recorded);
  solution.status = ok || unrecorded_stop ? report.status : Status::NonFinite;
  std::ostringstream message;
  message << "shooting (" << (options.analytic_jacobian ? "analytic" : "finite-difference")
          << " Jacobian, xi scale " << format_value(s) << "): " << report.message << ", " << solution.sweeps
          << " sweeps";
  if (!failure.empty()) message << "; last failed sweep: " << failure;
  if (unrecorded_stop) message << "; stopped before a sweep completed: no trajectory";
  solution.message = message.str();
  solution.solve_time_s = detail::seconds_since(start);
  return solution;
}

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_shooting(const TransportedProblem<G, L>& problem, const ShootingOptions& options = {}) {
  problem.validate();
  return solve_shooting(problem, options, geodesic_guess(problem), groups::CovectorOf<G>::Zero());
}

}  // namespace cartan::transported
