#pragma once
// The Lie-group kernel (kernels/lie_group/) presented in the manifold kernel's vocabulary
// (kernels/manifold/): general::solve's shooting kernel on a Lie group with the Cartan–Schouten
// connection (docs/design/lie-kernel.md), chosen in methods/solve.hpp. Neither kernel includes
// this header nor the other kernel; it includes both.
// The general problem on GroupManifold<G>::cartan_schouten(lambda), with frame0 the identity (the
// default), is the paper's problem (principle/group_problem.hpp) with the same lambda, T, N and
// endpoints, and the same Lagrangian of the transported velocity v
// (LieLagrangian below, the inverse of OnGroupManifold). The two schemes are then the same
// discrete equations (docs/general-connections.md#reduction; design §2.1), with
//   E_k = P_k = Ad(h_k)  and  xi = C(Xi),  C(Xi)_i = sum_{k,n} Xi(k, n) [e_k, e_i]^n,
// so general::solve (methods/solve.hpp) shoots on the Lie-group scheme, 2m unknowns (v0, xi0) instead of
// m + m^2 (v0, Xi0), and converts its result (general_solution_from_lie):
//   * the frame E_k = Ad(h_k), h_0 = e, h_{k+1} = exp(-lambda h u_k) h_k (disc-exp), u_k the step's
//     velocity: P_k v_k at order 1, the mean of P_k v_k and the predictor's P* v* at order 2; the
//     predictor is replayed by the scheme's own order-1 step, the same operations as the sweep's;
//   * Xi by the backward recursion Xi_N = C^+ xi_N, Xi_k = Xi_{k+1} - D_k, with D_k the step's
//     increment of Xi (disc-aux: -h v_k mu_k^T; at order 2 the mean with the predictor's) and C^+
//     the pseudo-inverse of C: the part of Xi in the kernel of C never feeds back (design §2.3);
//   * terminal_error and xi_terminal by the general definitions, and general's rule for the status:
//     never a wrong "converged" (design §2.4), applied once, by the Lie kernel's problem family
//     (LieKernelProblem), to every shooting (the continuation path's included): every result
//     converted is one of them.
// On a group with a centre (H3) C is not onto: xi's central components have no Xi behind them;
// they are constant (rate 0) and vanish at a root with the rest of xi_N (design §2.1, item 3).

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/manifold/solution.hpp"
#include "cartan/manifolds/geometry.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/mechanics/manifold_lagrangian.hpp"
#include "cartan/mechanics/manifold_lagrangian_hessian.hpp"
#include "cartan/methods/lie_group/continuation.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/numerics/spectrum.hpp"
#include "cartan/principle/manifold_problem.hpp"
#include "cartan/solvers/continuation.hpp"

namespace cartan::general {

/// Whether M is a GroupManifold (general::solve's choice of kernel: methods/solve.hpp).
template <class M>
inline constexpr bool kIsGroupManifold = false;
template <groups::LieGroup G>
inline constexpr bool kIsGroupManifold<manifolds::GroupManifold<G>> = true;

/// A Lagrangian of the general problem on GroupManifold<G> as a reduced Lagrangian of the Lie-group
/// solvers (mechanics::ReducedLagrangian), in the identity frame at g0: the inverse of
/// OnGroupManifold (mechanics/manifold_lagrangian.hpp). Both take the transported velocity v, left-trivialised at g0
/// (design §1.2), and both perturb g as g exp(e w): the point gradient is the left-trivialised group
/// gradient, and the Hessian blocks are the same. Its Hessian structure is the wrapped Lagrangian's,
/// reported at run time (mechanics::RuntimeHessianStructure).
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
struct LieLagrangian {
  L lagrangian;
  manifolds::GroupManifold<G> manifold;  ///< for the Hessian, whose point derivative steps on it

  double value(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return lagrangian.value(t, g, v);
  }
  groups::CovectorOf<G> momentum(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return lagrangian.momentum(t, g, v);
  }
  groups::CovectorOf<G> group_gradient(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return lagrangian.point_gradient(t, g, v);
  }
  groups::TangentOf<G> velocity(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return lagrangian.velocity(t, g, mu);
  }
  /// The Lagrangian's own second derivatives where it has them, central differences otherwise
  /// (mechanics/manifold_lagrangian_hessian.hpp).
  mechanics::LagrangianHessian<G> hessian(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    const LagrangianHessian<manifolds::GroupManifold<G>> h = general::lagrangian_hessian(manifold, lagrangian, t, g, v);
    return {h.momentum_v, h.momentum_q, h.gradient_v, h.gradient_q};
  }
  /// The manifold Lagrangian's structure (its point gradient is the group gradient here).
  mechanics::RuntimeHessianStructure hessian_structure() const { return mechanics::hessian_structure_of(lagrangian); }
};

/// C(Xi) (design §1.2): the paper's xi of the general auxiliary Xi (rows k index velocity, columns
/// n momentum), C(Xi)_i = sum_{k,n} Xi(k, n) [e_k, e_i]^n, i.e. the sum over the rows of
/// ad*_{e_k} Xi(k, :)^T. Then C(v mu^T) = ad*_v mu: Xi' = -v mu^T maps to xi' = -ad*_v mu
/// (disc-aux), and the curvature term of mu' is -lambda (1 - lambda) ad*_v C(Xi)
/// (docs/general-connections.md#reduction).
template <groups::LieGroup G>
groups::CovectorOf<G> aux_to_xi(const groups::AlgebraMatrixOf<G>& Xi) {
  groups::CovectorOf<G> xi = groups::CovectorOf<G>::Zero();
  for (int k = 0; k < G::kDim; ++k) {
    xi += groups::coad<G>(groups::TangentOf<G>::Unit(k), groups::CovectorOf<G>(Xi.row(k).transpose()));
  }
  return xi;
}

/// The matrix of C on Xi reshaped column by column (m x m^2).
template <groups::LieGroup G>
Eigen::Matrix<double, G::kDim, G::kDim * G::kDim> aux_to_xi_matrix() {
  constexpr int m = G::kDim;
  Eigen::Matrix<double, m, m * m> c;
  for (int n = 0; n < m; ++n) {
    for (int k = 0; k < m; ++k) {
      groups::AlgebraMatrixOf<G> unit = groups::AlgebraMatrixOf<G>::Zero();
      unit(k, n) = 1;
      c.col(k + n * m) = aux_to_xi<G>(unit);
    }
  }
  return c;
}

/// C^+, the Moore–Penrose pseudo-inverse of C (m^2 x m: Xi = C^+ xi reshaped), and sigma, the
/// smallest nonzero singular value of C (sqrt 2 on so(3) and se(3), 1 on se(2) and on h3, where C
/// has rank 2: design §2.1). Xi = C^+ xi is the smallest Xi with C(Xi) = xi for xi in the image of
/// C, and |C^+ xi| <= |xi| / sigma.
template <groups::LieGroup G>
struct AuxPseudoInverse {
  Eigen::Matrix<double, G::kDim * G::kDim, G::kDim> matrix;
  double smallest_singular_value = std::numeric_limits<double>::infinity();  ///< infinite where C = 0
};

/// Computed once per group (numerics::pseudo_inverse: an SVD of the m x m^2 matrix of C).
template <groups::LieGroup G>
const AuxPseudoInverse<G>& aux_pseudo_inverse() {
  static const AuxPseudoInverse<G> inverse = [] {
    const numerics::PseudoInverse c_plus = numerics::pseudo_inverse(aux_to_xi_matrix<G>());
    return AuxPseudoInverse<G>{c_plus.matrix, c_plus.smallest_singular_value};
  }();
  return inverse;
}

/// C^+ xi as an auxiliary (design §2.3).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> xi_to_aux(const groups::CovectorOf<G>& xi) {
  const Eigen::Matrix<double, G::kDim * G::kDim, 1> flat = aux_pseudo_inverse<G>().matrix * xi;
  return flat.reshaped(G::kDim, G::kDim);
}

/// The Lie-group problem of a general problem on GroupManifold<G>::cartan_schouten(lambda) (design
/// §1.1): the same lambda, T, N and endpoints, the Lagrangian through LieLagrangian. A type of its own
/// so that its shooting family (below) applies general's status rule to every shooting of the
/// continuation path, as the general kernel does inside solve_general_shooting.
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
struct LieKernelProblem : transported::TransportedProblem<G, LieLagrangian<G, L>> {};

template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
LieKernelProblem<G, L> lie_kernel_problem(const GeneralProblem<manifolds::GroupManifold<G>, L>& problem, double lambda) {
  return {{LieLagrangian<G, L>{problem.lagrangian, problem.manifold}, lambda, problem.T, problem.N, problem.q0,
           problem.qT}};
}

/// Whether the general problem is the Lie-group kernel's (design §1.3, §5.2): a Cartan–Schouten
/// connection given by its lambda (GroupManifold::cartan_schouten; the same connection given by its
/// coefficients keeps the general kernel) and frame0 unset or exactly the identity.
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
bool lie_kernel_available(const GeneralProblem<manifolds::GroupManifold<G>, L>& problem) {
  return problem.manifold.cartan_schouten_lambda().has_value() &&
         (!problem.frame0 || *problem.frame0 == groups::AlgebraMatrixOf<G>::Identity());
}

/// Whether general::solve runs its shooting on the Lie-group kernel: where it is available and the
/// method shoots (collocation is the general one).
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
bool lie_kernel_applies(const GeneralProblem<manifolds::GroupManifold<G>, L>& problem,
                        const SolveOptions& options) {
  return lie_kernel_available(problem) && options.method != Method::Collocation;
}

namespace detail {

/// General's "never a wrong converged" (solve_general_shooting; docs/general-connections.md, cut
/// locus) on a Lie-group result, design §2.4: a converged result becomes NotConverged when
/// difference(qT, q_N) is not a logarithm (the cut locus of qT) or separation(qT, q_N) > tol. On a
/// group where C^+ can enlarge xi (a nonzero singular value of C below 1; none of the shipped
/// groups), also when the general residual |(r_q, |Xi_N| / s)| > tol, Xi_N = C^+ xi_N.
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
void apply_general_status_rule(const LieKernelProblem<G, L>& problem, transported::TransportedSolution<G>& s,
                               double tol) {
  if (!s.converged() || s.trajectory.g.empty()) return;
  const manifolds::GroupManifold<G>& manifold = problem.lagrangian.manifold;
  const groups::ElementOf<G>& last = s.trajectory.g.back();
  std::string why;
  if (!manifolds::checked_difference(manifold, problem.gT, last).reaches) {
    why = "q_N = " + format_value(last) + " is where difference(qT, .) is not defined (the cut locus of qT)";
  } else {
    const double error = manifolds::separation(manifold, problem.gT, last);
    // sigma >= 1 up to the SVD's rounding: |C^+ xi_N| <= |xi_N|, which the Lie test has bounded.
    const bool may_enlarge = aux_pseudo_inverse<G>().smallest_singular_value < 1 - 1e-12;
    const double xi_size =
        may_enlarge ? xi_to_aux<G>(s.trajectory.xi.back()).norm() / transported::xi_scale(problem) : 0.0;
    if (!(error <= tol) || !(std::hypot(error, xi_size) <= tol)) {
      why = "q_N is " + format_value(error) + " from qT" +
            (may_enlarge ? " and |Xi_N| / s = " + format_value(xi_size) : std::string());
    }
  }
  if (why.empty()) return;
  s.status = Status::NotConverged;
  s.message += "; but " + why + ": not converged";
}

}  // namespace detail

}  // namespace cartan::general

namespace cartan::solvers {

/// The Lie kernel's problems as a family of the continuation path: the Lie-group shooting of the
/// kernel's problem behind the erased Lagrangian (compiled in the library on the shipped groups:
/// methods/lie_group/shooting.hpp; the erased type forwards every call, so the same operations), then
/// general's status rule (general::detail::apply_general_status_rule) at the shooting's tolerance.
template <groups::LieGroup G, general::ManifoldLagrangian<manifolds::GroupManifold<G>> L>
struct ShootingFamily<general::LieKernelProblem<G, L>>
    : ShootingFamily<transported::TransportedProblem<G, general::LieLagrangian<G, L>>> {
  using Lie = ShootingFamily<transported::TransportedProblem<G, general::LieLagrangian<G, L>>>;
  static typename Lie::Solution shoot(const general::LieKernelProblem<G, L>& p, const ShootingOptions& o,
                                      const typename Lie::Velocity& v, const typename Lie::Auxiliary& a) {
    const transported::TransportedProblem<G, general::LieLagrangian<G, L>>& typed = p;
    typename Lie::Solution s = transported::solve_shooting(transported::erased(typed), o, v, a);
    general::detail::apply_general_status_rule(p, s, o.tolerance);
    return s;
  }
};

}  // namespace cartan::solvers

namespace cartan::general {

/// The general scheme's trajectory at the Lie-group scheme's nodes `lie` of `problem` at `order`
/// (header comment; design §2.2, §2.3): t, q = g, v and mu moved in, the frame and Xi rebuilt. The
/// replay makes the sweep's own floating-point operations, so on a trajectory that satisfies the
/// scheme step by step (every shooting result) the frame is the sweep's Ad(h_k) to the bit.
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
GeneralTrajectory<manifolds::GroupManifold<G>> general_trajectory_from_lie(const LieKernelProblem<G, L>& problem,
                                                                           SchemeOrder order,
                                                                           transported::TransportedTrajectory<G>&& lie) {
  using Tangent = groups::TangentOf<G>;
  using Matrix = groups::AlgebraMatrixOf<G>;
  // The order-2 step's predictor is its order-1 step (kernels/lie_group/scheme.hpp: step), on the
  // problem behind the erased Lagrangian as the kernel's shooting (the same operations).
  const transported::TransportedProblem<G, LieLagrangian<G, L>>& typed = problem;
  const transported::ErasedProblem<G> erased = transported::erased(typed);
  const transported::TransportedScheme<G, mechanics::ErasedLagrangian<G>> euler(erased, SchemeOrder::First);
  const double dt = euler.step_size();
  const std::size_t nodes = lie.t.size();
  GeneralTrajectory<manifolds::GroupManifold<G>> out;
  out.frame.reserve(nodes);
  out.Xi.reserve(nodes);
  groups::ElementOf<G> transport = G::identity();  // h_0 = e (scheme.hpp: initial)
  for (std::size_t k = 0; k < nodes; ++k) {
    out.frame.push_back(G::Ad(transport));  // E_k = P_k
    if (k + 1 == nodes) break;
    const Tangent u = out.frame.back() * lie.v[k];  // disc-body-v
    Tangent step_u = u;
    Matrix rate = -lie.v[k] * lie.mu[k].transpose();  // Xi' = -v mu^T (kernels/manifold/scheme.hpp: rates)
    if (order == SchemeOrder::Second) {
      const transported::SchemeNode<G> node{lie.t[k], lie.g[k], transport, lie.mu[k], lie.xi[k], lie.v[k]};
      transported::SchemeNode<G> predictor;
      euler.step(node, predictor);
      step_u = (u + Tangent(G::Ad(predictor.transport) * predictor.v)) / 2;  // the rates' mean (Heun)
      rate = (rate + Matrix(-predictor.v * predictor.mu.transpose())) / 2;
    }
    out.Xi.push_back(dt * rate);  // D_k, until the backward pass below
    // disc-exp, as the scheme's step: h_{k+1} = exp(-lambda (h u)) h_k.
    const Tangent hu = dt * step_u;
    transport = G::compose(G::exp(Tangent(-problem.lambda * hu)), transport);
  }
  out.Xi.push_back(xi_to_aux<G>(lie.xi.back()));  // Xi_N = C^+ xi_N
  for (std::size_t k = nodes - 1; k-- > 0;) out.Xi[k] = out.Xi[k + 1] - out.Xi[k];  // Xi_k = Xi_{k+1} - D_k
  out.t = std::move(lie.t);
  out.q = std::move(lie.g);
  out.v = std::move(lie.v);
  out.mu = std::move(lie.mu);
  return out;
}

/// A Lie-kernel result as the general solve's (design §2.4): the trajectory converted
/// (general_trajectory_from_lie), Xi0 its Xi_0 (with its part in the kernel of C, so not C^+ xi0),
/// terminal_error = separation(qT, q_N) and xi_terminal = |Xi_N|, the status as it is (`lie` is a
/// shooting of LieKernelProblem's family, a continuation path's result or a method's through
/// lie_solve (below): general's status rule applied), the method as it is, the message
/// prefixed with "Lie-group kernel (Cartan–Schouten, lambda = ...): ".
/// The counters are the Lie kernel's: inner_iterations Levenberg–Marquardt's, summed over the
/// stages of a continuation in T (as the general kernel's); sweeps and residual_history are the Lie kernel's (2m
/// unknowns, not m + m^2). A result without a trajectory keeps none.
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
GeneralSolution<manifolds::GroupManifold<G>> general_solution_from_lie(const LieKernelProblem<G, L>& problem,
                                                                       transported::TransportedSolution<G>&& lie) {
  GeneralSolution<manifolds::GroupManifold<G>> out;
  static_cast<ResultCore&>(out) = std::move(static_cast<ResultCore&>(lie));
  out.message = "Lie-group kernel (Cartan–Schouten, lambda = " + format_value(problem.lambda) + "): " + out.message;
  out.action = std::numeric_limits<double>::quiet_NaN();  // a general result has none (ResultCore)
  out.terminal_error = out.xi_terminal = 0;  // the general definitions, below, where there is a trajectory
  out.v0 = lie.v0;
  if (lie.trajectory.t.empty()) return out;
  try {
    out.trajectory = general_trajectory_from_lie(problem, static_cast<SchemeOrder>(lie.order), std::move(lie.trajectory));
  } catch (const ModelError&) {
    throw;
  } catch (const std::exception& e) {  // a replay of steps the sweep made: not expected
    if (out.converged()) out.status = Status::NotConverged;
    out.message += "; rebuilding the frame and Xi failed: " + std::string(e.what());
    out.trajectory = {};
    return out;
  }
  out.Xi0 = out.trajectory.Xi.front();
  out.terminal_error = manifolds::separation(problem.lagrangian.manifold, problem.gT, out.trajectory.q.back());
  out.xi_terminal = out.trajectory.Xi.back().norm();
  return out;
}

namespace detail {

/// The Lie-group kernel's guess (xi0 = C(Xi0), a trajectory's xi = C(Xi)): design §4.
template <groups::LieGroup G>
transported::SolveGuess<G> lie_guess(const GeneralGuess<manifolds::GroupManifold<G>>& guess) {
  transported::SolveGuess<G> lie;
  lie.v0 = guess.v0;
  if (guess.Xi0) lie.xi0 = aux_to_xi<G>(*guess.Xi0);
  if (guess.trajectory) {
    const GeneralTrajectory<manifolds::GroupManifold<G>>& x = *guess.trajectory;
    transported::TransportedTrajectory<G> path;
    path.t = x.t;
    path.g = x.q;
    path.v = x.v;
    path.mu = x.mu;
    for (const auto& Xi : x.Xi) path.xi.push_back(aux_to_xi<G>(Xi));
    lie.trajectory = std::move(path);
  }
  return lie;
}

/// A method of the Lie-group kernel (header comment): transported::solve of the kernel's problem
/// with its Lagrangian behind the erased type, then general's status rule.
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
transported::TransportedSolution<G> lie_solve(const LieKernelProblem<G, L>& kernel, const SolveOptions& options,
                                              const transported::SolveGuess<G>& guess) {
  transported::TransportedSolution<G> s = transported::solve(transported::erased(kernel), options, guess);
  apply_general_status_rule(kernel, s, options.tol);
  return s;
}

/// The Lie-group kernel as a shooting kernel of the manifold kernel's methods (run_strategy,
/// methods/manifold/solve.hpp, its header comment): the family of LieKernelProblem, a guess Xi0 as
/// xi0 = C(Xi0) (its part in the kernel of C cannot enter, design §4), results converted; on a group
/// the library compiles (transported::kCompiledGroup) also its continuation in lambda (on the
/// kernel's family, general's status rule on every stage), multiple shooting and two-level
/// (lie_solve), and the Lie-group solve's first shooting window (so that Auto takes its path).
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
struct LieKernel {
  using Problem = LieKernelProblem<G, L>;
  static constexpr bool kHasGroupMethods = transported::kCompiledGroup<G>;
  Problem problem;

  const Problem& shooting_problem() const { return problem; }
  groups::CovectorOf<G> auxiliary(const groups::AlgebraMatrixOf<G>& Xi0) const { return aux_to_xi<G>(Xi0); }
  GeneralSolution<manifolds::GroupManifold<G>> result(transported::TransportedSolution<G>&& s) const {
    return general_solution_from_lie(problem, std::move(s));
  }
  double lambda() const { return problem.lambda; }
  int first_shooting_window() const { return ContinuationOptions{}.no_progress_window; }
  solvers::PathResultPtr continue_in_lambda(const ContinuationOptions& options, double start) const {
    return solvers::wrap<Problem>(solvers::detail::continue_in_lambda(problem, start, options));
  }
  /// Multiple shooting or two-level (options.method), as transported::solve runs them, from `guess`.
  solvers::PathResultPtr run(const SolveOptions& options, const GeneralGuess<manifolds::GroupManifold<G>>& guess) const {
    return solvers::wrap<Problem>(lie_solve(problem, options, lie_guess(guess)));
  }
};

}  // namespace detail

}  // namespace cartan::general
