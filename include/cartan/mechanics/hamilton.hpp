#pragma once
// The global Hamilton equations with a connection (eq:HE-1 on a Lie group: Hamilton-Lie),
//   g' = d_p H,   D/dt p + p(i_g' T) = -d^nabla_g H,
// for any left- or right-invariant connection, in trivialised form (the Lie–Poisson reduction
// theorem and its right version in appendix "Right formalism"). With mu the trivialised momentum
// (g^{-1} p on the left, p g^{-1} on the right), v = dh/dmu and zeta_h the trivialised dh/dg of
// the Hamiltonian reduced on the connection's side:
//   D/dt p          -> mu' - nabla*_v mu                   (eq:cov-curve-left-dual),
//   p(i_g' T)       -> tau,  tau_i = mu . T(v, E_i)        (eq:torsion-left, torsion()),
//   d^nabla_g H     -> zeta_h + (nabla v)^* mu             (eq:hor-diff-2; hor-diff-curve with the
//                      dual transport eq:parr-left-dual: d/de h(g_e, mu_e), mu_e' = nabla*_w mu_e).
// As for Euler–Lagrange (euler_lagrange.hpp), each term is evaluated with the connection as
// written: the connection-dependent parts cancel, leaving eq:LP-left / eq:LP-right, and the tests
// measure the cancellation and check each term against its coordinate definition.

#include "cartan/connections/invariant_connection.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lie_group_integrator.hpp"

namespace cartan::mechanics {

/// The three trivialised terms of (Hamilton-Lie) at one point (v = dh/dmu, mu, zeta_h).
template <groups::LieGroup G>
struct HamiltonTerms {
  groups::CovectorOf<G> covariant;   ///< -nabla*_v mu: D/dt p is trivialised to mu' + covariant
  groups::CovectorOf<G> torsion;     ///< tau_i = mu . T(v, E_i)
  groups::CovectorOf<G> horizontal;  ///< zeta_h + (nabla v)^* mu, the trivialised d^nabla_g H

  /// (Hamilton-Lie) solved for mu': mu' = -horizontal - torsion - covariant.
  groups::CovectorOf<G> momentum_rate() const { return -horizontal - torsion - covariant; }
};

template <groups::LieGroup G>
HamiltonTerms<G> hamilton_terms(const connections::InvariantConnection<G>& connection, const groups::TangentOf<G>& v,
                                const groups::CovectorOf<G>& mu, const groups::CovectorOf<G>& zeta_h) {
  HamiltonTerms<G> terms;
  terms.covariant = -connection.nabla_dual(v, mu);
  terms.torsion = connection.torsion_dual(v, mu);
  terms.horizontal = zeta_h + connection.nabla_operator_first(v).transpose() * mu;
  return terms;
}

/// Integrates (Hamilton-Lie) for `connection` over [0, T] in `steps` RKMK4 steps from g(0) = g0
/// and mu(0) = mu0, with the trivialisation of the connection's side (g' = g v or v g,
/// v = dh/dmu). The Hamiltonian must be reduced on that side. Throws std::invalid_argument like
/// lie_poisson.
template <groups::LieGroup G, ReducedHamiltonian<G> H>
Trajectory<G> hamilton(const connections::InvariantConnection<G>& connection, const H& hamiltonian,
                       const groups::ElementOf<G>& g0, const groups::CovectorOf<G>& mu0, double T, int steps) {
  validate_initial_value_problem<G>("hamilton", g0, "mu0", mu0, T, steps);
  const auto rate = [&](double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) {
    const groups::TangentOf<G> v = hamiltonian.velocity(t, g, mu);
    return ReducedRate<G>{v, hamilton_terms<G>(connection, v, mu, hamiltonian.group_gradient(t, g, mu)).momentum_rate()};
  };
  return integrate_rkmk4<G>(connection.side(), rate, g0, mu0, T, steps);
}

}  // namespace cartan::mechanics
