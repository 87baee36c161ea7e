#pragma once
// Classical (initial-value) Euler–Poincaré reduction (paper §4, thm-EP and appendix "Right
// formalism"): for a reduced Lagrangian l (lagrangian.hpp) with mu = dl/dv, v = the inverse
// Legendre map of mu and zeta the trivialised dl/dg,
//   Side::Left  (eq:EP-left):   mu' - ad*_v mu = zeta,    g' = g v,   l = l_-(g, v = g^{-1} g'),
//   Side::Right (eq:EP-right):  mu' + ad*_v mu = zeta,    g' = v g,   l = l_+(g, v = g' g^{-1}),
// integrated with RKMK4 (lie_group_integrator.hpp). The Lagrangian must be reduced on `side`.

#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lie_group_integrator.hpp"

namespace cartan::mechanics {

/// Integrates eq:EP-left or eq:EP-right over [0, T] in `steps` RKMK4 steps from g(0) = g0 and
/// the (left- or right-trivialised) velocity v(0) = v0. Throws std::invalid_argument for
/// T <= 0, steps < 1, a non-finite T or v0, or an invalid g0 (G::validate).
template <groups::LieGroup G, ReducedLagrangian<G> L>
Trajectory<G> euler_poincare(groups::Side side, const L& lagrangian, const groups::ElementOf<G>& g0, const groups::TangentOf<G>& v0,
                             double T, int steps) {
  validate_initial_value_problem<G>("euler_poincare", g0, "v0", v0, T, steps);
  const auto zeta = [&](double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>&, const groups::TangentOf<G>& v) {
    return groups::CovectorOf<G>(lagrangian.group_gradient(t, g, v));
  };
  return integrate_coadjoint_flow<G>(side, lagrangian, zeta, g0, lagrangian.momentum(0.0, g0, v0), T, steps);
}

}  // namespace cartan::mechanics
