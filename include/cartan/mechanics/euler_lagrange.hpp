#pragma once
// The global Euler–Lagrange equation with a connection (EL-Lie),
//   D/dt (d_g'L) + d_g'L(i_g' T) = d^nabla_g L,
// for any left- or right-invariant connection, in trivialised form (proof of thm-EP; right
// version in appendix "Right formalism"). With v = g^{-1} g' (left) or g' g^{-1} (right),
// mu = dl/dv and zeta the trivialised dl/dg of the Lagrangian reduced on the connection's side:
//   D/dt (d_g'L)       -> mu' - nabla*_v mu                 (eq:cov-curve-left-dual),
//   d_g'L(i_g' T)      -> tau,  tau_i = mu . T(v, E_i)      (eq:torsion-left, torsion()),
//   d^nabla_g L        -> zeta - (nabla v)^* mu             ((nabla v) w = nabla_w v).
// Each term is evaluated with the connection as written, not simplified by hand: the
// connection-dependent parts cancel (thm-EP, the connection-independence remark), leaving
// eq:EP-left / eq:EP-right, and the tests measure that cancellation numerically.

#include "cartan/connections/invariant_connection.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lie_group_integrator.hpp"

namespace cartan::mechanics {

/// The three trivialised terms of (EL-Lie) at one point (g, v, mu, zeta).
template <groups::LieGroup G>
struct EulerLagrangeTerms {
  groups::CovectorOf<G> covariant;   ///< -nabla*_v mu: D/dt (d_g'L) is trivialised to mu' + covariant
  groups::CovectorOf<G> torsion;     ///< tau_i = mu . T(v, E_i)
  groups::CovectorOf<G> horizontal;  ///< zeta - (nabla v)^* mu

  /// (EL-Lie) solved for mu': mu' = horizontal - torsion - covariant.
  groups::CovectorOf<G> momentum_rate() const { return horizontal - torsion - covariant; }
};

template <groups::LieGroup G>
EulerLagrangeTerms<G> euler_lagrange_terms(const connections::InvariantConnection<G>& connection, const groups::TangentOf<G>& v,
                                           const groups::CovectorOf<G>& mu, const groups::CovectorOf<G>& zeta) {
  EulerLagrangeTerms<G> terms;
  terms.covariant = -connection.nabla_dual(v, mu);
  terms.torsion = connection.torsion_dual(v, mu);
  terms.horizontal = zeta - connection.nabla_operator_first(v).transpose() * mu;
  return terms;
}

/// Integrates (EL-Lie) for `connection` over [0, T] in `steps` RKMK4 steps from g(0) = g0 and
/// v(0) = v0, with the trivialisation of the connection's side (g' = g v or v g). The Lagrangian
/// must be reduced on that side. Throws std::invalid_argument like euler_poincare.
template <groups::LieGroup G, ReducedLagrangian<G> L>
Trajectory<G> euler_lagrange(const connections::InvariantConnection<G>& connection, const L& lagrangian, const groups::ElementOf<G>& g0,
                             const groups::TangentOf<G>& v0, double T, int steps) {
  validate_initial_value_problem<G>("euler_lagrange", g0, "v0", v0, T, steps);
  const auto rate = [&](double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) {
    const groups::TangentOf<G> v = lagrangian.velocity(t, g, mu);
    return ReducedRate<G>{v,
                          euler_lagrange_terms<G>(connection, v, mu, lagrangian.group_gradient(t, g, v)).momentum_rate()};
  };
  return integrate_rkmk4<G>(connection.side(), rate, g0, lagrangian.momentum(0.0, g0, v0), T, steps);
}

}  // namespace cartan::mechanics
