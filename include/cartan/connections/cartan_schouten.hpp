#pragma once
// Cartan–Schouten connections (paper §5): the bi-invariant family with left bilinear map
//   nabla^L_v w = lambda [v, w]            (CS-conn)
// and right bilinear map
//   nabla^R_v w = (lambda - 1) [v, w]      (CS-conn-right),
// torsion and curvature on the algebra (tor-cur-lie-alg)
//   T(v,w) = (2 lambda - 1)[v,w],   R(u,v)w = lambda (lambda - 1) [[u,v],w],
// lambda = 0: (-)-connection (flat, transport = left translation); lambda = 1: (+)-connection
// (flat, transport = right translation); lambda = 1/2: torsion-free, R = -1/4 [[u,v],w].

#include "cartan/errors.hpp"
#include "cartan/connections/invariant_connection.hpp"

namespace cartan::connections {

/// The Cartan–Schouten connection of parameter lambda (any real number), described by its left
/// (CS-conn) or right (CS-conn-right) bilinear map. Throws std::invalid_argument if lambda is
/// not finite.
template <groups::LieGroup G>
InvariantConnection<G> cartan_schouten(double lambda, groups::Side side = groups::Side::Left) {
  require_finite(lambda, "cartan_schouten", "lambda");
  const double c = side == groups::Side::Left ? lambda : lambda - 1;
  typename InvariantConnection<G>::Coefficients gamma;
  for (int i = 0; i < G::kDim; ++i) gamma[i] = c * G::ad(groups::TangentOf<G>::Unit(i));
  return InvariantConnection<G>(side, gamma);
}

/// Closed form (tor-cur-lie-alg): T(v, w) = (2 lambda - 1)[v, w].
template <groups::LieGroup G>
groups::TangentOf<G> cartan_schouten_torsion(double lambda, const groups::TangentOf<G>& v, const groups::TangentOf<G>& w) {
  require_finite(lambda, "cartan_schouten_torsion", "lambda");
  return (2 * lambda - 1) * groups::bracket<G>(v, w);
}

/// Closed form (tor-cur-lie-alg): R(u, v) w = lambda (lambda - 1) [[u, v], w].
template <groups::LieGroup G>
groups::TangentOf<G> cartan_schouten_curvature(double lambda, const groups::TangentOf<G>& u, const groups::TangentOf<G>& v,
                                       const groups::TangentOf<G>& w) {
  require_finite(lambda, "cartan_schouten_curvature", "lambda");
  return lambda * (lambda - 1) * groups::bracket<G>(groups::bracket<G>(u, v), w);
}

}  // namespace cartan::connections
