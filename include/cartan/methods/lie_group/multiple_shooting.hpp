#pragma once
// Multiple shooting (beyond the paper; docs/paper-notes.md#erratum-4) on the same discrete scheme as
// single shooting: the N steps are split at nodes 0 = k_0 < k_1 < ... < k_M = N into M
// segments, each swept from its own start state, and one Levenberg–Marquardt problem solves
// for all start states at once. Its solution is the discrete solution of single shooting (the
// segments join exactly); the hope is that the lifted Newton iteration is less nonlinear over
// long horizons. Measured (test_multiple_shooting.cpp): it does not rescue the T = 12
// oscillator from the geodesic guess - LM ends on a fold of the lifted system (singular
// Jacobian, a local minimum of |r|) for every M tried; continuation in T is the robust path.
//
// Unknowns: segment 0 starts at (g0, h = e, mu(v0), xi0) with unknowns (v0, xi0); segment j >= 1
// at (g_j, h_j, mu_j, xi_j), with the group elements in charts around reference elements,
// g_j = gref_j exp(x_g) and h_j = exp(x_h) href_j, so that the unknowns are a plain vector
// (chain rule: gamma = J_r(x_g) dx_g, chi = J_l(x_h) dx_h). The references come from one sweep
// from the initial guess (so the initial residual is single shooting's at that guess) and are
// re-centred (x_g, x_h moved into them) between rounds of `recentre_every` iterations.
// Residuals: at each interior boundary j the continuity of the state,
//   (log(g_j^{-1} g_end), log(h_end h_j^{-1}), mu_end - mu_j, xi_end - xi_j)
// (g_end etc. the end of segment j - 1), and at k_M = N the terminal conditions
// (log(gT^{-1} g_N), xi_N): 4n(M - 1) + 2n equations in as many unknowns.
// Jacobian: analytic, from one tangent-linear sweep per segment (2n directions for segment 0,
// 4n for the others); a full pass over the segments steps every node once and counts as one
// sweep.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "cartan/methods/lie_group/shooting.hpp"
#include "cartan/solvers/multiple_shooting.hpp"

namespace cartan::transported {

struct MultipleShootingOptions {
  SchemeOrder order = SchemeOrder::First;
  std::optional<int> segments = std::nullopt;  ///< M; unset: default_segments(N)
  double tolerance = 1e-10;     ///< on the lifted residual and on one plain sweep's |(log(gT^{-1} g_N), xi_N)|
  int max_iterations = 100;     ///< Levenberg–Marquardt iterations over all rounds
  int recentre_every = 10;      ///< iterations per round; the charts are re-centred between rounds
  const SolveMonitor* monitor = nullptr;  ///< progress and stop requests; may be null

  void validate() const {
    if (segments && *segments < 1) {
      throw_invalid("MultipleShootingOptions", "segments", std::to_string(*segments), "must be at least 1");
    }
    require_finite(tolerance, "MultipleShootingOptions", "tolerance");
    if (!(tolerance > 0)) {
      throw_invalid("MultipleShootingOptions", "tolerance", format_value(tolerance), "must be positive");
    }
    if (max_iterations < 1) {
      throw_invalid("MultipleShootingOptions", "max_iterations", std::to_string(max_iterations), "must be at least 1");
    }
    if (recentre_every < 1) {
      throw_invalid("MultipleShootingOptions", "recentre_every", std::to_string(recentre_every), "must be at least 1");
    }
    require_scheme_order(order, "MultipleShootingOptions");
  }
};

/// Default number of segments: about 100 steps each, at most 16. The dense LM algebra costs
/// O(((4M - 2) n)^3) per iteration and overtakes the tangent sweep beyond M ~ 20 at N = 800;
/// more segments did not make the T = 12 oscillator converge either.
inline int default_segments(int steps) { return std::clamp(steps / 100, 1, 16); }

/// The lifted system of multiple shooting: its unknowns, residual and analytic Jacobian.
/// Public so that tests can check the Jacobian; solve_multiple_shooting drives it. Keeps a
/// reference to the scheme, which must outlive it.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class MultipleShootingSystem {
 public:
  using Scheme = TransportedScheme<G, L>;
  using Node = SchemeNode<G>;
  using NodeTangent = typename Scheme::NodeTangent;
  static constexpr int n = G::kDim;

  /// Segments of (nearly) equal length: k_j = floor(j N / M). Throws unless 1 <= M <= N.
  MultipleShootingSystem(const Scheme& scheme, int segments) : scheme_(scheme) {
    const int steps = scheme.problem().N;
    if (segments < 1 || segments > steps) {
      throw_invalid("MultipleShootingSystem", "segments", std::to_string(segments),
                    "must be between 1 and N = " + std::to_string(steps));
    }
    for (int j = 0; j <= segments; ++j) {
      boundary_.push_back(static_cast<int>(static_cast<long long>(j) * steps / segments));
    }
  }

  int segments() const { return static_cast<int>(boundary_.size()) - 1; }
  /// The segment sweeps poll `monitor`'s stop_pending (sweep.hpp); may be null.
  void set_monitor(const SolveMonitor* monitor) { monitor_ = monitor; }
  Eigen::Index size() const { return offset(segments()); }
  const std::string& failure() const { return failure_; }

  /// References from one sweep from (v0, xi0) up to k_{M-1}; returns the unknowns of that
  /// trajectory (chart coordinates 0), or nothing if the sweep failed (failure() says why).
  std::optional<Eigen::VectorXd> initialise(const groups::TangentOf<G>& v0, const groups::CovectorOf<G>& xi0) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(size());
    x.head<n>() = v0;
    x.segment<n>(n) = xi0;
    reference_ = {};
    SweepOutput<G, L> out;
    try {
      out.last = scheme_.initial(v0, xi0);
    } catch (const ModelError&) {
      throw;  // the model's defect, not a failed iterate
    } catch (const std::exception& e) {
      failure_ = e.what();
      return std::nullopt;
    }
    out.after_stop = 0;  // a stop here leaves no iterate: nothing follows it
    for (int j = 1; j < segments(); ++j) {
      if (!run(j - 1, out.last, std::nullopt, out)) return std::nullopt;
      reference_.push_back(out.last);
      x.segment<n>(offset(j) + 2 * n) = out.last.mu;
      x.segment<n>(offset(j) + 3 * n) = out.last.xi;
    }
    return x;
  }

  /// Moves the chart coordinates of x into the references (x_g = x_h = 0 afterwards).
  void recentre(Eigen::VectorXd& x) {
    for (int j = 1; j < segments(); ++j) {
      Node& ref = reference_[static_cast<std::size_t>(j) - 1];
      ref.g = G::compose(ref.g, G::exp(groups::TangentOf<G>(x.segment<n>(offset(j)))));
      ref.transport = G::compose(G::exp(groups::TangentOf<G>(x.segment<n>(offset(j) + n))), ref.transport);
      x.segment<2 * n>(offset(j)).setZero();
    }
  }

  /// Initial (v0, xi0) encoded in x.
  static groups::TangentOf<G> v0(const Eigen::VectorXd& x) { return x.head<n>(); }
  static groups::CovectorOf<G> xi0(const Eigen::VectorXd& x) { return x.segment<n>(n); }

  /// Residual at x and, if jac is set, its Jacobian. Dense although block-bidiagonal: with
  /// (4M - 2) n <= a few hundred unknowns the dense LM algebra costs at most a few sweeps
  /// (default_segments). Returns false, with failure() set, if a segment's sweep failed.
  bool evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    const int m = segments();
    r.setZero(size());
    if (jac) jac->setZero(size(), size());
    std::vector<Node> start(static_cast<std::size_t>(m));
    std::vector<NodeTangent> dstart(jac ? static_cast<std::size_t>(m) : 0);
    try {
      for (int j = 0; j < m; ++j) start_node(x, j, start[static_cast<std::size_t>(j)],
                                            jac ? &dstart[static_cast<std::size_t>(j)] : nullptr);
    } catch (const ModelError&) {
      throw;  // the model's defect, not a failed iterate
    } catch (const std::exception& e) {
      failure_ = e.what();
      return false;
    }
    for (int j = 0; j < m; ++j) {
      // Between segments as inside each (where steps are fast its sweep polls every 1024 steps,
      // SolveMonitor::stop_pending_at, more than a short segment has): a stop is a failed evaluation, which the solver's
      // next stop_requested() ends (128 segments of 15 steps ran a whole Jacobian, 0.1-0.3 s, past
      // a time limit).
      if (monitor_ != nullptr && monitor_->stop_pending()) {
        failure_ = "stopped before segment " + std::to_string(j) + " (time limit or cancellation)";
        return false;
      }
      SweepOutput<G, L> out;
      std::optional<NodeTangent> d;
      if (jac) d = std::move(dstart[static_cast<std::size_t>(j)]);
      if (!run(j, start[static_cast<std::size_t>(j)], std::move(d), out)) return false;
      const Eigen::Index row = offset(j + 1) - 2 * n;  // rows of the conditions at k_{j+1}
      const Eigen::Index col = offset(j), cols = offset(j + 1) - offset(j);
      if (j == m - 1) {
        const groups::TangentOf<G> rg = scheme_.terminal_residual(out.last);
        r.segment<2 * n>(row) << rg, out.last.xi;
        if (jac) {
          jac->block(row, col, n, cols) = scheme_.terminal_residual_tangent(rg, *out.tangent);
          jac->block(row + n, col, n, cols) = out.tangent->xi;
        }
        continue;
      }
      const Node& next = start[static_cast<std::size_t>(j) + 1];
      const groups::TangentOf<G> dg = groups::log_between<G>(next.g, out.last.g);
      const groups::TangentOf<G> dh = G::log(G::compose(out.last.transport, G::inverse(next.transport)));
      r.segment<4 * n>(row) << dg, dh, out.last.mu - next.mu, out.last.xi - next.xi;
      if (!jac) continue;
      // End of segment j: g_end exp(gamma) moves dg by J_r(dg)^{-1} gamma, exp(chi) h_end moves
      // dh by J_l(dh)^{-1} chi. Start of segment j + 1: g exp(gamma) moves dg by
      // -J_l(dg)^{-1} gamma and exp(chi) h moves dh by -J_r(dh)^{-1} chi, with gamma, chi the
      // chart Jacobians J_r(x_g), J_l(x_h) (the start tangent's identity blocks).
      const NodeTangent& e = *out.tangent;
      jac->block(row, col, n, cols) = groups::right_jacobian_inverse<G>(dg) * e.gamma;
      jac->block(row + n, col, n, cols) = groups::left_jacobian_inverse<G>(dh) * e.chi;
      jac->block(row + 2 * n, col, n, cols) = e.mu;
      jac->block(row + 3 * n, col, n, cols) = e.xi;
      const Eigen::Index next_col = offset(j + 1);
      const auto [xg, xh] = charts(x, j + 1);
      jac->block<n, n>(row, next_col) = -groups::left_jacobian_inverse<G>(dg) * groups::right_jacobian<G>(xg);
      jac->block<n, n>(row + n, next_col + n) = -groups::right_jacobian_inverse<G>(dh) * groups::left_jacobian<G>(xh);
      jac->block<n, n>(row + 2 * n, next_col + 2 * n) = -groups::AlgebraMatrixOf<G>::Identity();
      jac->block<n, n>(row + 3 * n, next_col + 3 * n) = -groups::AlgebraMatrixOf<G>::Identity();
    }
    return true;
  }

 private:
  /// First unknown of segment j: 2n for segment 0, 4n for each later one.
  Eigen::Index offset(int j) const { return j == 0 ? 0 : 2 * n + 4 * n * static_cast<Eigen::Index>(j - 1); }

  std::pair<groups::TangentOf<G>, groups::TangentOf<G>> charts(const Eigen::VectorXd& x, int j) const {
    return {x.segment<n>(offset(j)), x.segment<n>(offset(j) + n)};
  }

  /// The start node of segment j at x and, if d is set, its tangent along segment j's unknowns.
  void start_node(const Eigen::VectorXd& x, int j, Node& node, NodeTangent* d) const {
    if (j == 0) {
      node = scheme_.initial(v0(x), xi0(x));
      if (d) *d = scheme_.initial_tangent(node, 2 * n);
      return;
    }
    const Node& ref = reference_[static_cast<std::size_t>(j) - 1];
    const auto [xg, xh] = charts(x, j);
    node.t = ref.t;
    node.g = G::compose(ref.g, G::exp(xg));
    node.transport = G::compose(G::exp(xh), ref.transport);
    node.mu = x.segment<n>(offset(j) + 2 * n);
    node.xi = x.segment<n>(offset(j) + 3 * n);
    node.v = scheme_.velocity(node.t, node.g, node.mu);
    if (!d) return;
    *d = scheme_.state_tangent(node);
    Eigen::MatrixXd chart = Eigen::MatrixXd::Identity(4 * n, 4 * n);  // d(gamma, chi, mu, xi) / d(unknowns)
    chart.topLeftCorner<n, n>() = groups::right_jacobian<G>(xg);
    chart.block<n, n>(n, n) = groups::left_jacobian<G>(xh);
    for (auto* m : {&d->gamma, &d->chi, &d->mu, &d->xi, &d->v}) *m = *m * chart;
  }

  bool run(int j, const Node& node, std::optional<NodeTangent> d, SweepOutput<G, L>& out) {
    const std::size_t s = static_cast<std::size_t>(j);
    out.monitor = monitor_;
    if (sweep_segment(scheme_, node, std::move(d), boundary_[s], boundary_[s + 1], nullptr, out)) return true;
    failure_ = "segment " + std::to_string(j) + ": " + out.failure;
    return false;
  }

  const Scheme& scheme_;
  std::vector<int> boundary_;   ///< k_0 .. k_M
  std::vector<Node> reference_; ///< reference start nodes of segments 1 .. M-1 (t, g, transport)
  std::string failure_;
  const SolveMonitor* monitor_ = nullptr;
};

namespace detail {

/// |(log(gT^{-1} g_N), xi_N)| of one plain sweep from (v0, xi0), or infinity if it failed.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
double single_sweep_residual(const TransportedScheme<G, L>& scheme, const groups::TangentOf<G>& v0, const groups::CovectorOf<G>& xi0) {
  SweepOutput<G, L> out;
  if (!forward_sweep(scheme, v0, xi0, nullptr, 0, out)) return std::numeric_limits<double>::infinity();
  return std::hypot(scheme.terminal_residual(out.last).norm(), out.last.xi.norm() / xi_scale(scheme.problem()));
}

/// The lifted system as the compiled driver sees it (solvers/multiple_shooting.hpp): one
/// recorded into `solution`, the guess (v0, xi0) its start.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class LiftedScheme final : public solvers::LiftedSystem {
 public:
  using System = MultipleShootingSystem<G, L>;
  LiftedScheme(const TransportedScheme<G, L>& scheme, System& system, const groups::TangentOf<G>& v0,
               const groups::CovectorOf<G>& xi0, TransportedSolution<G>& solution)
      : scheme_(scheme), system_(system), v0_(v0), xi0_(xi0), solution_(solution) {}

  std::optional<Eigen::VectorXd> initialise() override { return system_.initialise(v0_, xi0_); }
  void recentre(Eigen::VectorXd& x) override { system_.recentre(x); }
  bool evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) override {
    return system_.evaluate(x, r, jac);
  }
  double single_sweep_residual(const Eigen::VectorXd& x) override {
    return detail::single_sweep_residual(scheme_, System::v0(x), System::xi0(x));
  }
  bool record(const Eigen::VectorXd& x) override {
    return detail::record_solution(scheme_, System::v0(x), System::xi0(x), nullptr, solution_);
  }
  double auxiliary_scale() const override { return xi_scale(scheme_.problem()); }
  const std::string& failure() const override { return system_.failure(); }

 private:
  const TransportedScheme<G, L>& scheme_;
  System& system_;
  groups::TangentOf<G> v0_;
  groups::CovectorOf<G> xi0_;
  TransportedSolution<G>& solution_;
};

}  // namespace detail

/// Multiple shooting from (v0_guess, xi0_guess); see the header comment. Converged means, as
/// for solve_shooting, that one plain sweep from the returned (v0, xi0) meets the tolerance:
/// the segments' joins leave defects that the sweep amplifies, so when the lifted residual is
/// below the tolerance but the sweep's is not, LM goes on with a proportionally tighter
/// tolerance (at most 3 times; then the status is "inconsistent"). The lifted residual reaches
/// ~1e-15, so this holds for tolerances above ~1e-15 times the sweep's sensitivity.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_multiple_shooting(const TransportedProblem<G, L>& problem,
                                               const MultipleShootingOptions& options, const groups::TangentOf<G>& v0_guess,
                                               const groups::CovectorOf<G>& xi0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_multiple_shooting", "v0_guess");
  require_finite(xi0_guess, "solve_multiple_shooting", "xi0_guess");
  const int segments = options.segments.value_or(default_segments(problem.N));
  if (segments > problem.N) {
    throw_invalid("MultipleShootingOptions", "segments", std::to_string(segments),
                  "must be at most N = " + std::to_string(problem.N));
  }
  using System = MultipleShootingSystem<G, L>;
  const auto start = std::chrono::steady_clock::now();
  const TransportedScheme<G, L> scheme(problem, options.order);
  System system(scheme, segments);
  system.set_monitor(options.monitor);
  TransportedSolution<G> solution;
  solution.method = Method::MultipleShooting;
  solution.order = static_cast<int>(options.order);
  solution.branch = "from the initial guess, segment states from a sweep from the guess";
  const std::string header = "multiple shooting (" + std::to_string(segments) + (segments == 1 ? " segment of ~" : " segments of ~") +
                             std::to_string(problem.N / segments) + " steps): ";
  detail::LiftedScheme<G, L> lifted(scheme, system, v0_guess, xi0_guess, solution);
  solvers::solve_lifted(lifted,
                        {.segments = segments, .tolerance = options.tolerance, .max_iterations = options.max_iterations,
                         .recentre_every = options.recentre_every, .monitor = options.monitor},
                        header, solution);
  solution.solve_time_s = detail::seconds_since(start);
  return solution;
}

/// From the paper's geodesic guess (v0 = log(g0^{-1} gT) / T, xi0 = 0).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_multiple_shooting(const TransportedProblem<G, L>& problem,
                                               const MultipleShootingOptions& options = {}) {
  problem.validate();
  return solve_multiple_shooting(problem, options, geodesic_guess(problem), groups::CovectorOf<G>::Zero());
}

}  // namespace cartan::transported
