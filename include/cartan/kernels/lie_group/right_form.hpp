#pragma once
// The transported-velocity principle in right-trivialised form (appendix "Right formalism" applied
// to §6; docs/paper-notes.md#right-form). The Cartan–Schouten transport written with right
// translations (second line of parr-tran-Cartan-lambda) is
//   Gamma(g)_s^t = d(R_g(t)) Texp((1 - lambda) int_s^t ad_{u_R(r)} dr) d(R_g(s)^{-1}),  u_R = g' g^{-1},
// so the transported velocity, right-trivialised at g0, is v_R = Q^{-1} u_R with
// Q(t) = Texp((1 - lambda) int_0^t ad_{u_R}) = Ad(q(t)), q' = (1 - lambda) u_R q. Torsion and
// curvature keep their algebra forms under right trivialisation at g0 (Ad(g0) is an automorphism of
// the bracket, tor-cur-lie-alg), so the momentum and auxiliary equations of eq:reduced-system read
// the same in right-trivialised quantities (v_R, mu_R, xi_R), with eta_R = Q^T zeta_R and zeta_R
// the right-trivialised dl/dg:
//   u_R = Ad(q) v_R,   g' = u_R g,   q' = (1 - lambda) u_R q,
//   mu_R' = Q^T zeta_R - (2 lambda - 1) ad*_{v_R} mu_R - lambda (1 - lambda) ad*_{v_R} xi_R,
//   xi_R' = -ad*_{v_R} mu_R.
// The sweep below is the paper's first-order discretisation of these equations (Lie–Euler on the
// right: g_{k+1} = exp(h u_R) g_k, q_{k+1} = exp((1 - lambda) h u_R) q_k; explicit Euler in
// mu_R, xi_R). It is the left scheme in other coordinates: v_R = Ad(g0) v, mu_R = Ad(g0)^{-T} mu,
// Q = Ad(g) P Ad(g0)^{-1}, and g_k is the same curve (tests/kernels/lie_group/test_right_form.cpp).
//
// The Lagrangian is the user's l(t, g, v) with v left-trivialised at g0 (principle/group_problem.hpp); its right
// form is l_R(t, g, v_R) = l(t, g, Ad(g0)^{-1} v_R).

#include "cartan/kernels/lie_group/scheme.hpp"

namespace cartan::transported {

/// The right-trivialised discrete trajectory: g_k and the right-trivialised (at g0) v_R, mu_R, xi_R.
template <groups::LieGroup G>
struct RightTrajectory {
  std::vector<groups::ElementOf<G>> g;
  std::vector<groups::TangentOf<G>> v;
  std::vector<groups::CovectorOf<G>> mu, xi;
};

/// The first-order right-form sweep (header comment) from v_R(0) = v0 and xi_R(0) = xi0 over the
/// problem's N steps. Throws std::invalid_argument for an invalid problem or non-finite start.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
RightTrajectory<G> right_form_sweep(const TransportedProblem<G, L>& problem, const groups::TangentOf<G>& v0,
                                    const groups::CovectorOf<G>& xi0) {
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;
  using Matrix = groups::AlgebraMatrixOf<G>;
  problem.validate();
  require_finite(v0, "right_form_sweep", "v0");
  require_finite(xi0, "right_form_sweep", "xi0");
  const double h = problem.step(), lambda = problem.lambda;
  const Matrix ad_g0 = G::Ad(problem.g0), ad_g0_inverse = G::Ad(G::inverse(problem.g0));
  const auto& l = problem.lagrangian;
  // l_R(t, g, v_R) = l(t, g, Ad(g0)^{-1} v_R): momentum, inverse Legendre map, zeta_R.
  const auto momentum = [&](double t, const groups::ElementOf<G>& g, const Tangent& v) -> Covector {
    return ad_g0_inverse.transpose() * l.momentum(t, g, Tangent(ad_g0_inverse * v));
  };
  const auto velocity = [&](double t, const groups::ElementOf<G>& g, const Covector& mu) -> Tangent {
    return ad_g0 * l.velocity(t, g, Covector(ad_g0.transpose() * mu));
  };
  // zeta_R . w = d/de l(exp(e w) g, v) = zeta_L . Ad(g^{-1}) w.
  const auto zeta = [&](double t, const groups::ElementOf<G>& g, const Tangent& v) -> Covector {
    return G::Ad(G::inverse(g)).transpose() * l.group_gradient(t, g, Tangent(ad_g0_inverse * v));
  };
  RightTrajectory<G> out;
  groups::ElementOf<G> g = problem.g0, q = G::identity();
  Tangent v = v0;
  Covector mu = momentum(0.0, g, v), xi = xi0;
  for (int k = 0;; ++k) {
    out.g.push_back(g), out.v.push_back(v), out.mu.push_back(mu), out.xi.push_back(xi);
    if (k == problem.N) break;
    const double t = k * h;
    const Matrix big_q = G::Ad(q);
    const Tangent u = big_q * v;
    const Covector coad_mu = groups::coad<G>(v, mu);
    const Covector dmu = big_q.transpose() * zeta(t, g, v) - (2 * lambda - 1) * coad_mu -
                         lambda * (1 - lambda) * groups::coad<G>(v, xi);
    g = G::compose(G::exp(Tangent(h * u)), g);
    q = G::compose(G::exp(Tangent((1 - lambda) * h * u)), q);
    mu += h * dmu;
    xi -= h * coad_mu;
    v = velocity(t + h, g, mu);
  }
  return out;
}

}  // namespace cartan::transported
