#pragma once
// The improvements the paper suggests for its scheme (appendix "Accuracy and improvement"),
// implemented as initial-value sweeps beside cartan's two orders (scheme.hpp), so that their
// orders and energy behaviour can be measured (tests/kernels/lie_group/test_scheme_variants.cpp,
// docs/paper-notes.md#erratum-3):
//
// * printed_magnus_sweep: the second-order Magnus transport step exactly as printed,
//     h_{k+1} = exp(Omega_1 + Omega_2) h_k,  Omega_1 = -lambda h u_k,
//     Omega_2 = -(lambda^2 h^2 / 12) [u_k, u*_{k+1}]
//   (in the algebra: [ad_a, ad_b] = ad_[a,b] and exp(ad_x) = Ad(exp x)), with u*_{k+1} from a
//   first-order predictor step, and every other update of the paper's first-order scheme. Omega_2
//   is O(h^3) ([u_k, u*_{k+1}] = O(h)) and Omega_1 takes the left end point, so the step stays
//   first order.
// * midpoint_sweep: the implicit midpoint rule for the momentum and auxiliary equations, with the
//   group and transport updates at the midpoint velocity (a symmetric, second-order step, the
//   "symplectic integrator" the paper suggests):
//     u_m = Ad(h_m) v_m,  h_m = exp(-lambda (h/2) u_m) h_k,  g_m = g_k exp((h/2) u_m),
//     mu_m = mu_k + (h/2) mu'(g_m, h_m, mu_m, xi_m),  xi_m = xi_k + (h/2) xi'(...),
//     then mu_{k+1} = 2 mu_m - mu_k, xi_{k+1} = 2 xi_m - xi_k, g_{k+1} = g_k exp(h u_m),
//     h_{k+1} = exp(-lambda h u_m) h_k,
//   solved by fixed-point iteration at each step. For l = 1/2 v . I v the energy is then conserved
//   exactly, for every lambda: mu_{k+1} - mu_k = h mu'_m and v_m . mu'_m = 0 by antisymmetry of
//   ad*_v (the continuous conservation law, docs/paper-notes.md#independent-checks, holds
//   step by step), with v_m = I^{-1} mu_m the mean of v_k and v_{k+1}.

#include <string>
#include <vector>

#include "cartan/kernels/lie_group/scheme.hpp"

namespace cartan::transported {

/// The printed Magnus step (header comment) from (v0, xi0) over the problem's N steps.
/// Throws std::invalid_argument for an invalid problem or non-finite start.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedTrajectory<G> printed_magnus_sweep(const TransportedProblem<G, L>& problem, const groups::TangentOf<G>& v0,
                                              const groups::CovectorOf<G>& xi0) {
  require_finite(v0, "printed_magnus_sweep", "v0");
  require_finite(xi0, "printed_magnus_sweep", "xi0");
  const TransportedScheme<G, L> scheme(problem, SchemeOrder::First);
  const double h = problem.step(), lambda = problem.lambda;
  TransportedTrajectory<G> out;
  out.reserve(static_cast<std::size_t>(problem.N) + 1);
  SchemeNode<G> node = scheme.initial(v0, xi0), next;
  out.push(node);
  for (int k = 0; k < problem.N; ++k) {
    const groups::TangentOf<G> u = scheme.rates(node).u;
    scheme.step(node, next);  // the first-order step: g, mu, xi, v, and the predictor of u_{k+1}
    const groups::TangentOf<G> u_next = scheme.rates(next).u;
    const groups::TangentOf<G> omega = -lambda * h * u - (lambda * lambda * h * h / 12) * groups::bracket<G>(u, u_next);
    next.transport = G::compose(G::exp(omega), node.transport);
    node = next;
    out.push(node);
  }
  return out;
}

struct MidpointOptions {
  double tolerance = 1e-14;  ///< on the change of (mu_m, xi_m, u_m) between iterations, relative
  int max_iterations = 100;  ///< per step
};

/// The implicit midpoint step (header comment) from (v0, xi0) over the problem's N steps.
/// Throws std::invalid_argument for an invalid problem or non-finite start, and
/// std::domain_error (naming the step) when the fixed-point iteration of a step does not
/// converge (h too large for the contraction).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedTrajectory<G> midpoint_sweep(const TransportedProblem<G, L>& problem, const groups::TangentOf<G>& v0,
                                        const groups::CovectorOf<G>& xi0, const MidpointOptions& options = {}) {
  require_finite(v0, "midpoint_sweep", "v0");
  require_finite(xi0, "midpoint_sweep", "xi0");
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;
  const TransportedScheme<G, L> scheme(problem, SchemeOrder::First);
  const double h = problem.step(), lambda = problem.lambda;
  TransportedTrajectory<G> out;
  out.reserve(static_cast<std::size_t>(problem.N) + 1);
  SchemeNode<G> node = scheme.initial(v0, xi0);
  out.push(node);
  for (int k = 0; k < problem.N; ++k) {
    // Midpoint state, iterated from the node's own rates.
    SchemeNode<G> mid = node;
    mid.t = node.t + h / 2;
    auto r = scheme.rates(node);
    bool converged = false;
    for (int it = 0; it < options.max_iterations && !converged; ++it) {
      const Tangent u = r.u;
      mid.g = G::compose(node.g, G::exp(Tangent(h / 2 * u)));
      mid.transport = G::compose(G::exp(Tangent(-lambda * h / 2 * u)), node.transport);
      const Covector mu = node.mu + h / 2 * r.dmu, xi = node.xi + h / 2 * r.dxi;
      if (!mechanics::all_finite(mu) || !mechanics::all_finite(xi)) break;  // diverged: reported below
      const double change = (mu - mid.mu).norm() + (xi - mid.xi).norm();
      const double size = 1 + mu.norm() + xi.norm();
      mid.mu = mu;
      mid.xi = xi;
      mid.v = scheme.velocity(mid.t, mid.g, mid.mu);
      r = scheme.rates(mid);
      converged = it > 0 && change <= options.tolerance * size && (r.u - u).norm() <= options.tolerance * (1 + u.norm());
    }
    if (!converged) {
      throw std::domain_error("midpoint_sweep: the fixed-point iteration of step " + std::to_string(k) +
                              " did not converge in " + std::to_string(options.max_iterations) +
                              " iterations (step h = " + format_value(h) + " too large)");
    }
    SchemeNode<G> next;
    next.t = node.t + h;
    next.g = G::compose(node.g, G::exp(Tangent(h * r.u)));
    next.transport = G::compose(G::exp(Tangent(-lambda * h * r.u)), node.transport);
    next.mu = 2 * mid.mu - node.mu;
    next.xi = 2 * mid.xi - node.xi;
    next.v = scheme.velocity(next.t, next.g, next.mu);
    node = next;
    out.push(node);
  }
  return out;
}

}  // namespace cartan::transported
