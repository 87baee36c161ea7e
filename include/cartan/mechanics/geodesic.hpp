#pragma once
// Geodesics of a left- or right-invariant connection: curves with D/dt g' = 0. In trivialised
// form (eq:cov-curve-left, its right version in appendix "Right formalism"), with v = g^{-1} g'
// (left) or g' g^{-1} (right),
//   v' = -nabla_v v,   g' = g v (left) or v g (right),
// integrated by RKMK4 (lie_group_integrator.hpp). For a Cartan connection (skew bilinear map,
// e.g. Cartan–Schouten, CS-conn) nabla_v v = 0: v is constant and the geodesics are the
// translates of one-parameter subgroups (paper §5, "Cartan connections"); RKMK4 then reproduces
// g0 exp(t v0) to rounding. For the Levi-Civita connection of a left-invariant metric the
// geodesics are the free motions of the metric's Lagrangian (Euler–Arnold).

#include "cartan/connections/invariant_connection.hpp"
#include "cartan/mechanics/lie_group_integrator.hpp"

namespace cartan::mechanics {

/// The geodesic of `connection` from g(0) = g0 with trivialised velocity v(0) = v0 over [0, T] in
/// `steps` RKMK4 steps; the trajectory's `mu` holds v as well (a geodesic has no momentum of its
/// own). Throws std::invalid_argument for T <= 0, steps < 1, a non-finite T or v0, or an invalid g0.
template <groups::LieGroup G>
Trajectory<G> geodesic(const connections::InvariantConnection<G>& connection, const groups::ElementOf<G>& g0,
                       const groups::TangentOf<G>& v0, double T, int steps) {
  validate_initial_value_problem<G>("geodesic", g0, "v0", v0, T, steps);
  const auto rate = [&](double, const groups::ElementOf<G>&, const groups::TangentOf<G>& v) {
    return ReducedRate<G>{v, groups::CovectorOf<G>(-connection.nabla(v, v))};
  };
  return integrate_rkmk4<G>(connection.side(), rate, g0, v0, T, steps);
}

}  // namespace cartan::mechanics
