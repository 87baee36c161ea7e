#pragma once
// The paper's two-level scheme (§7 "A two-level scheme", appendix pseudocode): an inner
// shooting loop on v0 by Levenberg–Marquardt with a forward-difference Jacobian and residual
// log(gT^{-1} g_N) for a fixed sequence {xi_k}, and an outer fixed-point iteration that
// recomputes {xi_k} by the backward recursion (disc-aux) until max_k |xi_new - xi_old| < tol.
// The plain fixed point has no convergence guarantee (docs/paper-notes.md#erratum-4); failures of
// either loop are reported with their iteration counts and residuals.

#include <sstream>

#include "cartan/transported/shooting.hpp"

namespace cartan::transported {

struct TwoLevelOptions {
  SchemeOrder order = SchemeOrder::First;
  double tolerance = 1e-8;         ///< outer: max_k |xi_new - xi_old| / xi_scale (shooting.hpp)
  double inner_tolerance = 1e-13;  ///< inner: |log(gT^{-1} g_N)| (far tighter than the outer one)
  int max_outer = 100;
  int max_inner = 100;
  bool analytic_jacobian = false;  ///< the paper uses finite differences
  const SolveMonitor* monitor = nullptr;  ///< progress and stop requests; may be null

  void validate() const {
    for (auto [name, value] : {std::pair{"tolerance", tolerance}, std::pair{"inner_tolerance", inner_tolerance}}) {
      require_finite(value, "TwoLevelOptions", name);
      if (!(value > 0)) throw_invalid("TwoLevelOptions", name, format_value(value), "must be positive");
    }
    if (max_outer < 1) throw_invalid("TwoLevelOptions", "max_outer", std::to_string(max_outer), "must be at least 1");
    if (max_inner < 1) throw_invalid("TwoLevelOptions", "max_inner", std::to_string(max_inner), "must be at least 1");
  }
};

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_two_level(const TransportedProblem<G, L>& problem, const TwoLevelOptions& options,
                                       const groups::TangentOf<G>& v0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_two_level", "v0_guess");
  constexpr int n = G::kDim;
  const auto start = std::chrono::steady_clock::now();
  const TransportedScheme<G, L> scheme(problem, options.order);
  const double dt = scheme.step_size();
  const std::size_t nodes = static_cast<std::size_t>(problem.N) + 1;
  TransportedSolution<G> solution;
  solution.method = Method::TwoLevel;
  solution.order = static_cast<int>(options.order);

  std::vector<groups::CovectorOf<G>> xi(nodes, groups::CovectorOf<G>::Zero());  // xi^(0) = 0 (Step 1)
  std::vector<groups::CovectorOf<G>> rates;
  std::string failure;
  auto inner_residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    SweepOutput<G, L> out;
    out.monitor = options.monitor;
    ++solution.sweeps;
    const int columns = (jac != nullptr && options.analytic_jacobian) ? n : 0;
    const auto begin = std::chrono::steady_clock::now();
    if (!forward_sweep(scheme, groups::TangentOf<G>(x), groups::CovectorOf<G>::Zero(), &xi, columns, out)) {
      failure = out.failure;
      return false;
    }
    // After a stop: a recording sweep (these sweeps record nothing).
    if (options.monitor) {
      options.monitor->reserve_after_stop(std::chrono::duration_cast<std::chrono::nanoseconds>(
          (std::chrono::steady_clock::now() - begin) * SolveMonitor::sweeps_after_stop(false, columns > 0)));
    }
    const groups::TangentOf<G> rg = scheme.terminal_residual(out.last);
    r = rg;
    if (columns > 0) *jac = scheme.terminal_residual_tangent(rg, *out.tangent);
    return true;
  };
  numerics::ResidualFunction inner = inner_residual;
  if (!options.analytic_jacobian) {
    inner = numerics::with_forward_difference_jacobian(
        [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) { return inner_residual(x, r, nullptr); }, 1e-7);
  }

  // The outer test max_k |xi_new - xi_old| < tolerance is relative to xi's size (shooting.hpp).
  const double scale = xi_scale(problem);
  // Until a loop decides, the status is the initial NotConverged.
  const auto decided = [](Status s) { return s != Status::NotConverged; };
  solution.status = Status::NotConverged;
  Eigen::VectorXd v0 = v0_guess;
  double change = std::numeric_limits<double>::infinity();
  numerics::NonlinearSolveReport report;
  std::ostringstream history;
  for (int outer = 0; outer < options.max_outer; ++outer) {
    solution.outer_iterations = outer + 1;
    // Steps 2-3: inner shooting for v0 with the current {xi_k}.
    report = numerics::levenberg_marquardt(inner, v0, {.tolerance = options.inner_tolerance, .max_iterations = options.max_inner,
                                             .monitor = options.monitor, .evaluations_stop = true});  // sweeps poll
    solution.inner_iterations += report.iterations;
    v0 = report.x;
    if (report.status != Status::Converged) {
      solution.status = report.status == Status::Interrupted ? Status::Interrupted : Status::InnerNotConverged;
      solution.message = "two-level: inner shooting failed in outer iteration " + std::to_string(outer + 1) + ": " +
                         report.message + (failure.empty() ? "" : "; last failed sweep: " + failure);
      break;
    }
    // Step 4: backward recursion xi_k = xi_{k+1} - h * rate_k with xi_N = 0 (disc-aux).
    SweepOutput<G, L> out;
    out.xi_rates = &rates;
    ++solution.sweeps;
    if (!forward_sweep(scheme, groups::TangentOf<G>(v0), groups::CovectorOf<G>::Zero(), &xi, 0, out)) {
      solution.status = Status::NonFinite;
      solution.message = "two-level: the sweep for the xi rates failed in outer iteration " +
                         std::to_string(outer + 1) + ": " + out.failure;
      break;
    }
    std::vector<groups::CovectorOf<G>> xi_new(nodes, groups::CovectorOf<G>::Zero());
    for (std::size_t k = nodes - 1; k-- > 0;) xi_new[k] = xi_new[k + 1] - dt * rates[k];
    change = 0;
    for (std::size_t k = 0; k < nodes; ++k) change = std::max(change, (xi_new[k] - xi[k]).cwiseAbs().maxCoeff());
    xi = std::move(xi_new);
    history << (outer ? ", " : "") << format_value(change);
    solution.residual_history.push_back(change);
    // Step 5: stop when the sequence no longer changes.
    if (change < options.tolerance * scale) {
      solution.status = Status::Converged;
      break;
    }
    if (!std::isfinite(change)) {
      solution.status = Status::NonFinite;
      break;
    }
  }
  if (!decided(solution.status)) solution.status = Status::OuterNotConverged;
  // Step 6: the trajectory for the final {xi_k}.
  ++solution.sweeps;
  if (!detail::record_solution(scheme, groups::TangentOf<G>(v0), groups::CovectorOf<G>::Zero(), &xi, solution)) {
    solution.status = Status::NonFinite;
  }
  std::ostringstream message;
  message << "two-level: " << to_string(solution.status) << " after " << solution.outer_iterations << " outer and "
          << solution.inner_iterations << " inner iterations, " << solution.sweeps
          << " sweeps; outer changes max|xi_new - xi_old| = [" << history.str() << "]; terminal error "
          << format_value(solution.terminal_error);
  if (!solution.message.empty()) message << "; " << solution.message;
  solution.message = message.str();
  solution.solve_time_s = detail::seconds_since(start);
  return solution;
}

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_two_level(const TransportedProblem<G, L>& problem, const TwoLevelOptions& options = {}) {
  problem.validate();
  return solve_two_level(problem, options, geodesic_guess(problem));
}

}  // namespace cartan::transported
