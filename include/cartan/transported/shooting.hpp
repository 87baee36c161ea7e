#pragma once
// Augmented shooting (beyond the paper): integrate xi forward from an unknown xi0 and solve for
// (v0, xi0) with the terminal conditions (log(gT^{-1} g_N), xi_N) = 0 in one Levenberg–Marquardt
// problem. Its solution satisfies the same discrete equations as the fixed point of the paper's
// two-level scheme (xi_k from the backward recursion with xi_N = 0), without the outer loop.
// The Jacobian is analytic (a tangent-linear sweep, one sweep per evaluation) or by forward
// differences (1 + 2n sweeps).

#include <chrono>
#include <sstream>

#include "cartan/nonlinear_solve.hpp"
#include "cartan/transported/solution.hpp"
#include "cartan/transported/sweep.hpp"

namespace cartan {

struct ShootingOptions {
  SchemeOrder order = SchemeOrder::First;
  double tolerance = 1e-10;     ///< on |(log(gT^{-1} g_N), xi_N)|
  int max_iterations = 100;     ///< Levenberg–Marquardt iterations
  bool analytic_jacobian = true;

  void validate() const {
    require_finite(tolerance, "ShootingOptions", "tolerance");
    if (!(tolerance > 0)) throw_invalid("ShootingOptions", "tolerance", format_value(tolerance), "must be positive");
    if (max_iterations < 1) {
      throw_invalid("ShootingOptions", "max_iterations", std::to_string(max_iterations), "must be at least 1");
    }
  }
};

/// The paper's initial guess: the body velocity of the geodesic from g0 to gT, log(g0^{-1} gT)/T.
template <LieGroup G, ReducedLagrangian<G> L>
TangentOf<G> geodesic_guess(const TransportedProblem<G, L>& problem) {
  return G::log(G::compose(G::inverse(problem.g0), problem.gT)) / problem.T;
}

namespace detail {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Final recorded sweep shared by the solvers: fills trajectory and terminal figures.
template <LieGroup G, ReducedLagrangian<G> L>
bool record_solution(const TransportedScheme<G, L>& scheme, const TangentOf<G>& v0, const CovectorOf<G>& xi0,
                     const std::vector<CovectorOf<G>>* given_xi, TransportedSolution<G>& solution) {
  SweepOutput<G, L> out;
  out.trajectory = &solution.trajectory;
  ++solution.sweeps;
  if (!forward_sweep(scheme, v0, xi0, given_xi, 0, out)) return false;
  solution.v0 = v0;
  solution.xi0 = out.trajectory->xi.front();
  solution.terminal_error = scheme.terminal_residual(out.last).norm();
  solution.xi_terminal = out.last.xi.norm();
  return true;
}

}  // namespace detail

template <LieGroup G, ReducedLagrangian<G> L>
TransportedSolution<G> solve_shooting(const TransportedProblem<G, L>& problem, const ShootingOptions& options,
                                      const TangentOf<G>& v0_guess, const CovectorOf<G>& xi0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_shooting", "v0_guess");
  require_finite(xi0_guess, "solve_shooting", "xi0_guess");
  constexpr int n = G::kDim;
  const auto start = std::chrono::steady_clock::now();
  const TransportedScheme<G, L> scheme(problem, options.order);
  TransportedSolution<G> solution;
  solution.method = "shooting";
  solution.order = static_cast<int>(options.order);
  std::string failure;

  auto unpack = [](const Eigen::VectorXd& x) {
    return std::pair<TangentOf<G>, CovectorOf<G>>(x.head<n>(), x.tail<n>());
  };
  auto residual_only = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    const auto [v0, xi0] = unpack(x);
    SweepOutput<G, L> out;
    ++solution.sweeps;
    if (!forward_sweep(scheme, v0, xi0, nullptr, 0, out)) {
      failure = out.failure;
      return false;
    }
    r.resize(2 * n);
    r << scheme.terminal_residual(out.last), out.last.xi;
    return true;
  };
  ResidualFunction f;
  if (options.analytic_jacobian) {
    f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
      if (jac == nullptr) return residual_only(x, r);
      const auto [v0, xi0] = unpack(x);
      SweepOutput<G, L> out;
      ++solution.sweeps;
      if (!forward_sweep(scheme, v0, xi0, nullptr, 2 * n, out)) {
        failure = out.failure;
        return false;
      }
      const TangentOf<G> rg = scheme.terminal_residual(out.last);
      r.resize(2 * n);
      r << rg, out.last.xi;
      jac->resize(2 * n, 2 * n);
      jac->topRows(n) = scheme.terminal_residual_tangent(rg, *out.tangent);
      jac->bottomRows(n) = out.tangent->xi;
      return true;
    };
  } else {
    f = with_forward_difference_jacobian(residual_only, 1e-7);
  }
  Eigen::VectorXd x0(2 * n);
  x0 << v0_guess, xi0_guess;
  const NonlinearSolveReport report =
      levenberg_marquardt(f, x0, {.tolerance = options.tolerance, .max_iterations = options.max_iterations});
  solution.inner_iterations = report.iterations;
  solution.residual_history = report.residual_history;
  const auto [v0, xi0] = unpack(report.x);
  const bool recorded = detail::record_solution(scheme, v0, xi0, nullptr, solution);
  solution.converged = report.status == SolveStatus::Converged && recorded;
  solution.status = recorded ? std::string(to_string(report.status)) : "non-finite";
  std::ostringstream message;
  message << "shooting (" << (options.analytic_jacobian ? "analytic" : "finite-difference")
          << " Jacobian): " << report.message << ", " << solution.sweeps << " sweeps";
  if (!failure.empty()) message << "; last failed sweep: " << failure;
  solution.message = message.str();
  solution.solve_time_s = detail::seconds_since(start);
  return solution;
}

template <LieGroup G, ReducedLagrangian<G> L>
TransportedSolution<G> solve_shooting(const TransportedProblem<G, L>& problem, const ShootingOptions& options = {}) {
  problem.validate();
  return solve_shooting(problem, options, geodesic_guess(problem), CovectorOf<G>::Zero());
}

}  // namespace cartan
