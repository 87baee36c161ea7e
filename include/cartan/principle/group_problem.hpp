#pragma once
// The two-point boundary-value problem of the connection-dependent variational principle
// (paper §6, eq:reduced-system) for a Cartan–Schouten connection of parameter lambda:
//   Gamma*(g)_t^0 dl/dg = mu' + (2 lambda - 1) ad*_v mu + lambda (1 - lambda) ad*_v xi,
//   xi' = -ad*_v mu,  xi(T) = 0,
//   g' = Gamma(g)_0^t v,  g(0) = g0,  g(T) = gT,   mu = dl/dv.
// v is the transported velocity, stored left-trivialised at g0 (docs/conventions.md).

#include <string>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/principle/horizon.hpp"
#include "cartan/principle/scales.hpp"

namespace cartan::transported {

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
struct TransportedProblem {
  L lagrangian;
  double lambda = 0.5;   ///< Cartan–Schouten parameter (any real number)
  double T = 1.0;        ///< final time
  int N = 100;           ///< number of steps, h = T / N
  groups::ElementOf<G> g0 = G::identity();
  groups::ElementOf<G> gT = G::identity();

  double step() const { return T / N; }

  /// Throws std::invalid_argument naming the first bad value.
  void validate() const {
    require_finite(lambda, "TransportedProblem", "lambda");
    require_horizon(T, N, "TransportedProblem");
    G::validate(g0, "g0");
    G::validate(gT, "gT");
  }
};

/// The paper's initial guess: the body velocity of the geodesic from g0 to gT, log(g0^{-1} gT)/T.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
groups::TangentOf<G> geodesic_guess(const TransportedProblem<G, L>& problem) {
  return groups::log_between<G>(problem.g0, problem.gT) / problem.T;
}

/// The unit of xi on this problem (aux_scale; methods/lie_group/shooting.hpp's header comment):
/// T |v_ref| |mu_ref|, v_ref the geodesic velocity at a speed of at least 1/T (aux_scale_velocity).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
double xi_scale(const TransportedProblem<G, L>& problem) {
  const groups::TangentOf<G> v = aux_scale_velocity(geodesic_guess(problem), problem.T);
  return aux_scale(problem.T, v.norm(), problem.lagrangian.momentum(0, problem.g0, v).norm());
}

/// xi's own size on this problem (aux_size): T |v| |mu| at the geodesic velocity, or 0.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
double xi_size(const TransportedProblem<G, L>& problem) {
  const groups::TangentOf<G> v = geodesic_guess(problem);
  return aux_size(problem.T, v.norm(), problem.lagrangian.momentum(0, problem.g0, v).norm());
}

}  // namespace cartan::transported
