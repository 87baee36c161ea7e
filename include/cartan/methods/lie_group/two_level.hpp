#pragma once
// The paper's two-level scheme (§7 "A two-level scheme", appendix pseudocode): an inner
// shooting loop on v0 by Levenberg–Marquardt with a forward-difference Jacobian and residual
// log(gT^{-1} g_N) for a fixed sequence {xi_k}, and an outer fixed-point iteration that
// recomputes {xi_k} by the backward recursion (disc-aux) until max_k |xi_new - xi_old| < tol.
// The plain fixed point has no convergence guarantee (docs/paper-notes.md#erratum-4); failures of
// either loop are reported with their iteration counts and residuals.

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "cartan/methods/lie_group/shooting.hpp"
#include "cartan/solvers/two_level.hpp"

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

namespace detail {

/// The scheme's sweeps as the compiled two-level driver sees them (solvers/two_level.hpp): the
/// inner residual log(gT^{-1} g_N) with the sequence xi held fixed (xi0 = 0), its update by the
/// backward recursion xi_k = xi_{k+1} - h rate_k with xi_N = 0 (disc-aux), the trajectory
/// recorded into `solution`.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class FixedPointScheme final : public solvers::FixedPointSystem {
 public:
  FixedPointScheme(const TransportedScheme<G, L>& scheme, const SolveMonitor* monitor, TransportedSolution<G>& solution)
      : scheme_(scheme), monitor_(monitor), solution_(solution),
        xi_(static_cast<std::size_t>(scheme.problem().N) + 1, groups::CovectorOf<G>::Zero()) {}  // xi^(0) = 0 (Step 1)

  bool inner(const Eigen::VectorXd& v0, Eigen::VectorXd& r, Eigen::MatrixXd* jac) override {
    SweepOutput<G, L> out;
    out.monitor = monitor_;
    const int columns = jac != nullptr ? G::kDim : 0;
    const auto begin = std::chrono::steady_clock::now();
    if (!forward_sweep(scheme_, groups::TangentOf<G>(v0), groups::CovectorOf<G>::Zero(), &xi_, columns, out)) {
      failure_ = out.failure;
      return false;
    }
    // After a stop: a recording sweep (these sweeps record nothing).
    if (monitor_) {
      monitor_->reserve_after_stop(std::chrono::duration_cast<std::chrono::nanoseconds>(
          (std::chrono::steady_clock::now() - begin) * SolveMonitor::sweeps_after_stop(false, columns > 0)));
    }
    const groups::TangentOf<G> rg = scheme_.terminal_residual(out.last);
    r = rg;
    if (columns > 0) *jac = scheme_.terminal_residual_tangent(rg, *out.tangent);
    return true;
  }
  std::optional<double> update(const Eigen::VectorXd& v0) override {
    SweepOutput<G, L> out;
    out.xi_rates = &rates_;
    if (!forward_sweep(scheme_, groups::TangentOf<G>(v0), groups::CovectorOf<G>::Zero(), &xi_, 0, out)) {
      failure_ = out.failure;
      return std::nullopt;
    }
    const double dt = scheme_.step_size();
    const std::size_t nodes = xi_.size();
    std::vector<groups::CovectorOf<G>> xi_new(nodes, groups::CovectorOf<G>::Zero());
    for (std::size_t k = nodes - 1; k-- > 0;) xi_new[k] = xi_new[k + 1] - dt * rates_[k];
    double change = 0;
    for (std::size_t k = 0; k < nodes; ++k) change = std::max(change, (xi_new[k] - xi_[k]).cwiseAbs().maxCoeff());
    xi_ = std::move(xi_new);
    return change;
  }
  bool record(const Eigen::VectorXd& v0) override {
    return record_solution(scheme_, groups::TangentOf<G>(v0), groups::CovectorOf<G>::Zero(), &xi_, solution_);
  }
  const std::string& failure() const override { return failure_; }

 private:
  const TransportedScheme<G, L>& scheme_;
  const SolveMonitor* monitor_;
  TransportedSolution<G>& solution_;
  std::vector<groups::CovectorOf<G>> xi_, rates_;
  std::string failure_;
};

}  // namespace detail

/// The two-level scheme (header comment) from v0_guess: the driver is compiled
/// (solvers::solve_fixed_point), the sweeps are this kernel's.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_two_level(const TransportedProblem<G, L>& problem, const TwoLevelOptions& options,
                                       const groups::TangentOf<G>& v0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_two_level", "v0_guess");
  const auto start = std::chrono::steady_clock::now();
  const TransportedScheme<G, L> scheme(problem, options.order);
  TransportedSolution<G> solution;
  solution.method = Method::TwoLevel;
  solution.order = static_cast<int>(options.order);
  detail::FixedPointScheme<G, L> system(scheme, options.monitor, solution);
  solvers::solve_fixed_point(system,
                             {.tolerance = options.tolerance, .auxiliary_scale = xi_scale(problem),
                              .inner_tolerance = options.inner_tolerance, .max_outer = options.max_outer,
                              .max_inner = options.max_inner, .analytic_jacobian = options.analytic_jacobian,
                              .monitor = options.monitor},
                             Eigen::VectorXd(v0_guess), solution);
  solution.solve_time_s = detail::seconds_since(start);
  return solution;
}

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_two_level(const TransportedProblem<G, L>& problem, const TwoLevelOptions& options = {}) {
  problem.validate();
  return solve_two_level(problem, options, geodesic_guess(problem));
}

}  // namespace cartan::transported
