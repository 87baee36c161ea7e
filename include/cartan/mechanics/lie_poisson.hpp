#pragma once
// Classical (initial-value) Lie–Poisson reduction (paper §4, lem:left-lie-poisson, and appendix
// "Right formalism"): for a reduced Hamiltonian h (lagrangian.hpp) with v = dh/dmu and zeta_h
// the trivialised dh/dg,
//   Side::Left  (eq:LP-left):   mu' - ad*_v mu = -zeta_h,   g' = g v,
//   Side::Right (eq:LP-right):  mu' + ad*_v mu = -zeta_h,   g' = v g,
// integrated with RKMK4 (lie_group_integrator.hpp). The Hamiltonian must be reduced on `side`.

#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lie_group_integrator.hpp"

namespace cartan::mechanics {

/// Integrates eq:LP-left or eq:LP-right over [0, T] in `steps` RKMK4 steps from g(0) = g0,
/// mu(0) = mu0. Throws std::invalid_argument for T <= 0, steps < 1, a non-finite T or mu0, or
/// an invalid g0 (G::validate).
template <groups::LieGroup G, ReducedHamiltonian<G> H>
Trajectory<G> lie_poisson(groups::Side side, const H& hamiltonian, const groups::ElementOf<G>& g0, const groups::CovectorOf<G>& mu0,
                          double T, int steps) {
  validate_initial_value_problem<G>("lie_poisson", g0, "mu0", mu0, T, steps);
  const auto minus_zeta_h = [&](double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu, const groups::TangentOf<G>&) {
    return groups::CovectorOf<G>(-hamiltonian.group_gradient(t, g, mu));
  };
  return integrate_coadjoint_flow<G>(side, hamiltonian, minus_zeta_h, g0, mu0, T, steps);
}

}  // namespace cartan::mechanics
