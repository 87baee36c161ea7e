#pragma once
// A discrete variational integrator of the transported principle (eq:action-conn-dep): the
// discrete Euler–Lagrange equations of the discrete action S_h of action.hpp, solved for the
// interior nodes of the two-point problem by Newton's method on the exact gradient.
//
// S_h on the piecewise-geodesic path through g_0..g_N (action.hpp), with a_k = log(g_k^{-1} g_{k+1})
// = h_k u_k (disc-grp), the transport element y_0 = e, y_{k+1} = exp(-lambda a_k) y_k, P_k = Ad(y_k)
// (disc-exp), the midpoint m_k = g_k exp(a_k / 2) and tau_k = t_k + h_k / 2:
//   S_h = sum_k h_k l(tau_k, m_k, v_k),   v_k = P_k^{-1} a_k / h_k   (disc-body-v)
// (the transported velocity is constant on a step: Ad(exp(x)) x = x, so the midpoint transport of
// action.hpp gives the same v_k).
//
// Gradient. G_j . w = d/de S_h(g_j -> g_j exp(e w)), left-trivialised (eq:w-left). By the
// conventions of exp_jacobian.hpp, g_{k+1} exp(e w) moves a_k by e J_r(a_k)^{-1} w and g_k exp(e w)
// by -e J_l(a_k)^{-1} w; at fixed a_k, g_k exp(e w) moves m_k by Ad(exp(-a_k/2)) w, and a change da
// of a_k moves it by J_r(a_k/2) da / 2. A change of y_k to exp(e chi) y_k changes v_k by
// P_k^{-1} ad(a_k) chi / h_k and y_{k+1} by chi_{k+1} = Ad(exp(-lambda a_k)) chi_k, while da_k adds
// -lambda J_l(-lambda a_k) da_k to chi_{k+1}. The costate of chi_k (the derivative of the steps
// k.. N-1 along chi_k) is rho_k = P_k^{-T} xi_k, where
//   xi_N = 0,   xi_k = xi_{k+1} + h_k ad*_{v_k} mu_k        (disc-aux, with midpoint values)
// (Ad is an automorphism: P^{-1} ad(a) = h ad(v) P^{-1}): the paper's auxiliary variable is the
// adjoint of the transport. With zeta_k, mu_k the left-trivialised dl/dg and dl/dv at
// (tau_k, m_k, v_k), and Ad(exp(x)) J_l(-x) = J_l(x):
//   alpha_k = dS_h/da_k = (h_k/2) J_r(a_k/2)^T zeta_k + P_k^{-T} mu_k - lambda J_l(lambda a_k)^T P_k^{-T} xi_{k+1},
//   beta_k  = dS_h/dg_k at fixed a_k = h_k Ad(exp(-a_k/2))^T zeta_k,
//   G_j = beta_j - J_l(a_j)^{-T} alpha_j + J_r(a_{j-1})^{-T} alpha_{j-1}   (j = 0: no last term; j = N: only it).
// One forward sweep (a_k, y_k, the model's callbacks, the Jacobians) and one reverse sweep: O(N).
// The discrete Euler–Lagrange equations are G_j = 0 for j = 1..N-1.
//
// Newton. The unknowns are the corrections delta_j of the interior nodes, g_j <- g_j exp(delta_j).
// The Hessian dG/d delta is formed by forward differences of the exact gradient, column by column
// (n (N-1) gradients; a perturbation of node j leaves the forward sweep before step j-1 unchanged,
// so only its rest is recomputed). Newton's fixed point G = 0 depends on the gradient alone; the
// difference Hessian's O(step) relative error (1e-7) only makes the last iterations linear with a
// contraction of that size. The dense LU costs (n (N-1))^3 / 3 per iteration: the method is for
// n (N-1) up to a few thousand. S_h is stationary at a solution, not necessarily minimal, so the
// damping is Deuflhard's affine-invariant natural monotonicity test on the simplified Newton
// correction (|H^{-1} G(trial)| <= (1 - s/4) |H^{-1} G|), not a decrease of S_h.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cartan/groups/exp_jacobian.hpp"
#include "cartan/kernels/lie_group/action.hpp"
#include "cartan/kernels/lie_group/solution.hpp"
#include "cartan/methods/lie_group/shooting.hpp"
#include "cartan/solvers/variational.hpp"

namespace cartan::transported {

/// S_h, its gradient at every node and the step quantities of the sweeps (header comment).
template <groups::LieGroup G>
struct ActionGradient {
  double action = 0;
  std::vector<groups::CovectorOf<G>> gradient;  ///< G_j, j = 0..N (the interior ones vanish at a solution)
  std::vector<groups::TangentOf<G>> u;          ///< body velocity of each step, log(g_k^{-1} g_{k+1}) / h_k
  std::vector<groups::TangentOf<G>> v;          ///< transported velocity of each step, P_k^{-1} u_k
  std::vector<groups::CovectorOf<G>> mu;        ///< dl/dv at each step's midpoint
  std::vector<groups::CovectorOf<G>> xi;        ///< xi_k at the nodes, k = 0..N (xi_N = 0)
};

namespace detail {

/// One step of S_h with the derivatives its gradient needs (header comment).
template <groups::LieGroup G>
struct ActionStep {
  using Matrix = groups::AlgebraMatrixOf<G>;
  groups::ElementOf<G> transport;  ///< y_k, P_k = Ad(y_k)
  groups::TangentOf<G> a, v;
  groups::CovectorOf<G> mu, zeta;
  double h = 0, value = 0;         ///< h_k and h_k l(tau_k, m_k, v_k)
  Matrix p_inverse_t;              ///< P_k^{-T}
  Matrix coad_v;                   ///< ad*_{v_k}
  Matrix half_right_jacobian_t;    ///< J_r(a_k/2)^T
  Matrix half_ad_t;                ///< Ad(exp(-a_k/2))^T
  Matrix transport_jacobian_t;     ///< J_l(lambda a_k)^T
  Matrix left_inverse_t;           ///< J_l(a_k)^{-T}
  Matrix right_inverse_t;          ///< J_r(a_k)^{-T}
};

/// The forward and reverse sweeps of the gradient of S_h on fixed times t.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class ActionSweep {
 public:
  using Step = ActionStep<G>;
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;
  using Element = groups::ElementOf<G>;

  ActionSweep(const L& lagrangian, double lambda, std::vector<double> t)
      : lagrangian_(lagrangian), lambda_(lambda), t_(std::move(t)) {}

  std::size_t steps() const { return t_.size() - 1; }

  /// Steps k = from..N-1 of the path g into `out` (size N; entries before `from` are kept: y_from
  /// is read from out[from]).
  void forward(const std::vector<Element>& g, std::vector<Step>& out, std::size_t from = 0) const {
    out.resize(steps());
    Element transport = from == 0 ? G::identity() : out[from].transport;
    for (std::size_t k = from; k < steps(); ++k) {
      Step& s = out[k];
      s.h = t_[k + 1] - t_[k];
      s.transport = transport;
      s.a = groups::log_between<G>(g[k], g[k + 1]);
      const Tangent half = s.a / 2;
      const auto [exp_minus_half, right_jacobian_half] = groups::exp_and_left_jacobian<G>(Tangent(-half));
      const auto [exp_lambda_a, left_jacobian_lambda] = groups::exp_and_left_jacobian<G>(Tangent(lambda_ * s.a));
      const Element midpoint = G::compose(g[k], G::inverse(exp_minus_half));
      const groups::AlgebraMatrixOf<G> p_inverse = G::Ad(G::inverse(transport));
      s.v = p_inverse * s.a / s.h;
      const double tau = t_[k] + s.h / 2;
      s.value = s.h * lagrangian_.value(tau, midpoint, s.v);
      s.mu = mechanics::require_finite_result(Covector(lagrangian_.momentum(tau, midpoint, s.v)), "lagrangian.momentum",
                                              tau, midpoint, s.v);
      s.zeta = mechanics::require_finite_result(Covector(lagrangian_.group_gradient(tau, midpoint, s.v)),
                                                "lagrangian.group_gradient", tau, midpoint, s.v);
      s.p_inverse_t = p_inverse.transpose();
      s.coad_v = groups::coad<G>(s.v);
      s.half_right_jacobian_t = right_jacobian_half.transpose();
      s.half_ad_t = G::Ad(exp_minus_half).transpose();
      s.transport_jacobian_t = left_jacobian_lambda.transpose();
      s.left_inverse_t = groups::left_jacobian_inverse<G>(s.a).transpose();
      s.right_inverse_t = groups::right_jacobian_inverse<G>(s.a).transpose();
      transport = G::compose(G::inverse(exp_lambda_a), transport);  // disc-exp
    }
  }

  /// The reverse sweep: xi_k (disc-aux) and G_j at every node into `xi`, `gradient` (size N+1).
  void reverse(const std::vector<Step>& steps, std::vector<Covector>& xi, std::vector<Covector>& gradient) const {
    const std::size_t N = steps.size();
    xi.assign(N + 1, Covector::Zero());
    gradient.assign(N + 1, Covector::Zero());
    for (std::size_t k = N; k-- > 0;) {
      const Step& s = steps[k];
      const Covector alpha = s.h / 2 * (s.half_right_jacobian_t * s.zeta) + s.p_inverse_t * s.mu -
                             lambda_ * (s.transport_jacobian_t * (s.p_inverse_t * xi[k + 1]));
      gradient[k] += s.h * (s.half_ad_t * s.zeta) - s.left_inverse_t * alpha;
      gradient[k + 1] += s.right_inverse_t * alpha;
      xi[k] = xi[k + 1] + s.h * (s.coad_v * s.mu);
    }
  }

 private:
  const L& lagrangian_;
  double lambda_;
  std::vector<double> t_;
};

}  // namespace detail

/// S_h and its exact left-trivialised gradient at every node of the path through g[k] at the
/// increasing times t[k] (header comment). Throws std::invalid_argument as transported_action.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
ActionGradient<G> transported_action_gradient(const L& lagrangian, double lambda, const std::vector<double>& t,
                                              const std::vector<groups::ElementOf<G>>& g) {
  detail::check_action_path<G>("transported_action_gradient", lambda, t, g);
  const detail::ActionSweep<G, L> sweep(lagrangian, lambda, t);
  std::vector<detail::ActionStep<G>> steps;
  sweep.forward(g, steps);
  ActionGradient<G> out;
  sweep.reverse(steps, out.xi, out.gradient);
  for (const auto& s : steps) {
    out.action += s.value;
    out.u.push_back(s.a / s.h);
    out.v.push_back(s.v);
    out.mu.push_back(s.mu);
  }
  return out;
}

/// As above at the uniform times k T / N (N = g.size() - 1).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
ActionGradient<G> transported_action_gradient(const L& lagrangian, double lambda, double T,
                                              const std::vector<groups::ElementOf<G>>& g) {
  if (g.size() < 2) {
    throw_invalid("transported_action_gradient", "g.size()", std::to_string(g.size()), "must be at least 2 (one step)");
  }
  return transported_action_gradient<G>(lagrangian, lambda,
                                        uniform_times("transported_action_gradient", T, g.size() - 1), g);
}

struct VariationalOptions {
  double tolerance = 1e-10;     ///< on max_j |delta_j|, the simplified Newton correction (radians)
  int max_iterations = 50;      ///< Newton iterations (Hessian evaluations)
  double hessian_step = 1e-7;   ///< forward-difference step of the Hessian (radians)
  const SolveMonitor* monitor = nullptr;  ///< progress and stop requests; may be null

  /// Throws std::invalid_argument naming the first bad value.
  void validate() const {
    for (auto [name, value] : {std::pair{"tolerance", tolerance}, std::pair{"hessian_step", hessian_step}}) {
      require_finite(value, "VariationalOptions", name);
      if (!(value > 0)) throw_invalid("VariationalOptions", name, format_value(value), "must be positive");
    }
    if (max_iterations < 1) {
      throw_invalid("VariationalOptions", "max_iterations", std::to_string(max_iterations), "must be at least 1");
    }
  }
};

/// The one-parameter subgroup from g0 to gT at the problem's N + 1 nodes (the default start).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
std::vector<groups::ElementOf<G>> geodesic_path(const TransportedProblem<G, L>& problem) {
  const groups::TangentOf<G> x = groups::log_between<G>(problem.g0, problem.gT);
  std::vector<groups::ElementOf<G>> g(static_cast<std::size_t>(problem.N) + 1);
  for (int k = 0; k <= problem.N; ++k) {
    g[static_cast<std::size_t>(k)] = G::compose(problem.g0, G::exp(groups::TangentOf<G>(x * k / problem.N)));
  }
  return g;
}

/// A trajectory's g at the problem's uniform nodes, on the one-parameter subgroup between the
/// samples around each node (the trajectory is validated on [0, T] by the caller, SolveGuess).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
std::vector<groups::ElementOf<G>> path_at_nodes(const TransportedProblem<G, L>& problem,
                                                const TransportedTrajectory<G>& trajectory) {
  const std::vector<double> times = uniform_times("path_at_nodes", problem.T, static_cast<std::size_t>(problem.N));
  std::vector<groups::ElementOf<G>> g(times.size());
  std::size_t i = 0;  // trajectory interval [t_i, t_{i+1}] of the node
  for (std::size_t k = 0; k < times.size(); ++k) {
    while (i + 2 < trajectory.t.size() && trajectory.t[i + 1] < times[k]) ++i;
    const double s = std::clamp((times[k] - trajectory.t[i]) / (trajectory.t[i + 1] - trajectory.t[i]), 0.0, 1.0);
    g[k] = G::compose(trajectory.g[i],
                      G::exp(groups::TangentOf<G>(s * groups::log_between<G>(trajectory.g[i], trajectory.g[i + 1]))));
  }
  return g;
}

namespace detail {

/// The Newton iteration of solve_variational on the interior nodes (header comment).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class VariationalNewton {
 public:
  static constexpr int n = G::kDim;
  using Element = groups::ElementOf<G>;
  using Covector = groups::CovectorOf<G>;
  using Step = ActionStep<G>;

  VariationalNewton(const TransportedProblem<G, L>& problem, const VariationalOptions& options)
      : sweep_(problem.lagrangian, problem.lambda,
               uniform_times("solve_variational", problem.T, static_cast<std::size_t>(problem.N))),
        options_(options), unknowns_(n * (problem.N - 1)) {}

  Eigen::Index unknowns() const { return unknowns_; }
  int gradients() const { return gradients_; }

  /// The gradient's interior entries at g into `out`, with the steps and xi it computed; false
  /// when a value is not finite.
  bool evaluate(const std::vector<Element>& g, std::vector<Step>& steps, Eigen::VectorXd& out,
                std::size_t from = 0) {
    ++gradients_;
    sweep_.forward(g, steps, from);
    sweep_.reverse(steps, xi_, gradient_);
    out.resize(unknowns_);
    for (Eigen::Index j = 0; j < unknowns_ / n; ++j) out.segment<n>(n * j) = gradient_[static_cast<std::size_t>(j) + 1];
    return out.allFinite();
  }
  const std::vector<Covector>& xi() const { return xi_; }

  /// Forward-difference Hessian at g, whose steps and gradient are `steps` and `base`; false when
  /// a value is not finite or the monitor has a stop pending (polled at every node: n gradient
  /// sweeps, at most a few milliseconds).
  bool hessian(const std::vector<Element>& g, const std::vector<Step>& steps, const Eigen::VectorXd& base,
               Eigen::MatrixXd& out) {
    out.resize(unknowns_, unknowns_);
    std::vector<Element> moved = g;
    std::vector<Step> scratch = steps;
    Eigen::VectorXd column;
    const double e = options_.hessian_step;
    for (Eigen::Index j = 0; j < unknowns_ / n; ++j) {
      if (SolveMonitor::poll(options_.monitor)) return false;
      const std::size_t node = static_cast<std::size_t>(j) + 1;
      for (int i = 0; i < n; ++i) {
        moved[node] = G::compose(g[node], G::exp(groups::TangentOf<G>(e * groups::TangentOf<G>::Unit(i))));
        if (!evaluate(moved, scratch, column, node - 1)) return false;
        out.col(n * j + i) = (column - base) / e;
      }
      moved[node] = g[node];
      std::copy(steps.begin() + static_cast<std::ptrdiff_t>(node - 1), steps.end(),
                scratch.begin() + static_cast<std::ptrdiff_t>(node - 1));
    }
    return true;
  }

 private:
  ActionSweep<G, L> sweep_;
  VariationalOptions options_;
  Eigen::Index unknowns_;
  int gradients_ = 0;
  std::vector<Covector> xi_, gradient_;
};

/// g_j exp(s delta_j) at the interior nodes.
template <groups::LieGroup G>
std::vector<groups::ElementOf<G>> moved_interior(const std::vector<groups::ElementOf<G>>& g, const Eigen::VectorXd& delta,
                                                 double s) {
  constexpr int n = G::kDim;
  std::vector<groups::ElementOf<G>> out = g;
  for (Eigen::Index j = 0; j < delta.size() / n; ++j) {
    const std::size_t node = static_cast<std::size_t>(j) + 1;
    out[node] = G::compose(g[node], G::exp(groups::TangentOf<G>(s * delta.segment<n>(n * j))));
  }
  return out;
}

/// v at the nodes from the steps' (constant) transported velocities, which are second-order values
/// at the steps' midpoints t_k + h/2: at node k the cubic through the four nearest midpoints (all
/// of them where N < 4), whose own error is O(h^4). Every node then carries the midpoint values'
/// smooth O(h^2) error and nothing else: the mean of two adjacent steps inside and a linear
/// extrapolation at the ends (before) added errors h^2 v''/8 and -3 h^2 v''/8, a jump that a
/// verifier's difference quotients turned into an O(h) residual at the first interior node (the
/// H3 oscillator, lambda = 1/2: 2.5e-4 against a threshold of 9.9e-5 at N = 400, falling only 2x
/// per halving of h).
template <groups::LieGroup G>
std::vector<groups::TangentOf<G>> node_velocities(const std::vector<groups::TangentOf<G>>& step_v) {
  const auto N = static_cast<std::ptrdiff_t>(step_v.size());
  const std::ptrdiff_t used = std::min<std::ptrdiff_t>(4, N);
  std::vector<groups::TangentOf<G>> v(step_v.size() + 1);
  for (std::ptrdiff_t k = 0; k <= N; ++k) {
    const std::ptrdiff_t first = std::clamp<std::ptrdiff_t>(k - used / 2, 0, N - used);  // midpoints first + 1/2 ..
    groups::TangentOf<G> value = groups::TangentOf<G>::Zero();
    for (std::ptrdiff_t i = first; i < first + used; ++i) {
      double weight = 1;  // Lagrange's basis polynomial of midpoint i at the node k
      for (std::ptrdiff_t j = first; j < first + used; ++j) {
        if (j != i) weight *= (static_cast<double>(k - j) - 0.5) / static_cast<double>(i - j);
      }
      value += weight * step_v[static_cast<std::size_t>(i)];
    }
    v[static_cast<std::size_t>(k)] = value;
  }
  return v;
}

/// The path of nodes as the compiled Newton iteration sees it (solvers/variational.hpp): the
/// current path `g` with its steps, and a trial path with its own.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class PathScheme final : public solvers::PathSystem {
 public:
  PathScheme(VariationalNewton<G, L>& newton, std::vector<groups::ElementOf<G>>& g, std::vector<ActionStep<G>>& steps)
      : newton_(newton), g_(g), steps_(steps) {}

  Eigen::Index unknowns() const override { return newton_.unknowns(); }
  bool gradient(Eigen::VectorXd& out) override { return newton_.evaluate(g_, steps_, out); }
  bool hessian(const Eigen::VectorXd& gradient, Eigen::MatrixXd& out) override {
    return newton_.hessian(g_, steps_, gradient, out);
  }
  bool trial(const Eigen::VectorXd& delta, double s, Eigen::VectorXd& gradient) override {
    trial_ = moved_interior<G>(g_, delta, s);
    return newton_.evaluate(trial_, trial_steps_, gradient);
  }
  void accept() override {
    g_ = trial_;
    std::swap(steps_, trial_steps_);
  }

 private:
  VariationalNewton<G, L>& newton_;
  std::vector<groups::ElementOf<G>>& g_;
  std::vector<ActionStep<G>>& steps_;
  std::vector<groups::ElementOf<G>> trial_;
  std::vector<ActionStep<G>> trial_steps_;
};

}  // namespace detail

/// Solves the discrete Euler–Lagrange equations of S_h for the interior nodes of `problem`
/// (header comment) from `start` (N + 1 nodes whose first and last are replaced by g0 and gT;
/// default: geodesic_path). Never throws for numerical trouble: the status says what happened
/// (Converged, MaxIterations, Stalled, NonFinite, SingularJacobian, Interrupted). Throws
/// std::invalid_argument for an invalid problem, options or start, and lets ModelError through.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_variational(const TransportedProblem<G, L>& problem, const VariationalOptions& options = {},
                                         const std::vector<groups::ElementOf<G>>* start = nullptr) {
  problem.validate();
  options.validate();
  const auto started = std::chrono::steady_clock::now();
  std::vector<groups::ElementOf<G>> g = start ? *start : geodesic_path(problem);
  if (g.size() != static_cast<std::size_t>(problem.N) + 1) {
    throw_invalid("solve_variational", "start.size()", std::to_string(g.size()),
                  "must be N + 1 = " + std::to_string(problem.N + 1));
  }
  for (std::size_t k = 1; k + 1 < g.size(); ++k) G::validate(g[k], "start[" + std::to_string(k) + "]");
  g.front() = problem.g0;
  g.back() = problem.gT;

  TransportedSolution<G> solution;
  solution.method = Method::Variational;
  solution.order = kVariationalOrder;
  detail::VariationalNewton<G, L> newton(problem, options);
  std::vector<detail::ActionStep<G>> steps;
  detail::PathScheme<G, L> path(newton, g, steps);
  const solvers::PathNewtonOutcome outcome =
      solvers::newton_on_path(path, {.tolerance = options.tolerance, .max_iterations = options.max_iterations,
                                     .monitor = options.monitor},
                              solution.residual_history);
  const Status status = outcome.status;
  const int iteration = outcome.iterations;

  // The result: the last accepted iterate (the start when nothing was accepted).
  Eigen::VectorXd gradient;
  newton.evaluate(g, steps, gradient);
  TransportedTrajectory<G>& tr = solution.trajectory;
  tr.t = uniform_times("solve_variational", problem.T, static_cast<std::size_t>(problem.N));
  tr.g = g;
  VariationalReport<G> report;
  solution.action = 0;
  for (const auto& step : steps) {
    report.step_u.push_back(step.a / step.h);
    report.step_v.push_back(step.v);
    solution.action += step.value;
  }
  tr.v = detail::node_velocities<G>(report.step_v);
  for (std::size_t k = 0; k < tr.t.size(); ++k) tr.mu.push_back(problem.lagrangian.momentum(tr.t[k], tr.g[k], tr.v[k]));
  tr.xi = newton.xi();
  report.gradient_norm = gradient.size() ? gradient.cwiseAbs().maxCoeff() : 0.0;
  report.unknowns = static_cast<int>(newton.unknowns());
  solution.v0 = tr.v.front();
  solution.xi0 = tr.xi.front();
  solution.terminal_error = 0;  // g_N = gT by construction
  solution.xi_terminal = 0;     // xi_N = 0 by construction
  solution.inner_iterations = iteration;
  solution.sweeps = newton.gradients();
  solution.status = status;
  std::ostringstream message;
  message << "variational (Newton on the exact gradient of S_h, " << report.unknowns << " unknowns): "
          << to_string(status) << " after " << iteration << " iterations, " << newton.gradients()
          << " gradient sweeps, max |gradient| = " << format_value(report.gradient_norm);
  if (!solution.residual_history.empty()) message << ", last correction " << format_value(solution.residual_history.back());
  if (!outcome.why.empty()) message << "; " << outcome.why;
  solution.message = message.str();
  solution.variational = std::move(report);
  solution.solve_time_s = detail::seconds_since(started);
  return solution;
}

}  // namespace cartan::transported
