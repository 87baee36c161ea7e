#pragma once
// Dense output of a sampled solution of the general problem (Result.sol in Python): at
// a node the sample itself; on the step [t_k, t_k+1], s = (t - t_k) / h, with x_k =
// difference(q_k, q_k+1) (the instance's piece through both nodes, manifolds/manifold.hpp):
//   q(t) = step(q_k, s x_k) and frame(t) = transport_along_step(q_k, s x_k) frame_k, the piece the
//   discrete schemes move along and the frame parallel along it (O(h^2) from the smooth solution
//   for every method);
//   the discrete schemes: v, mu, Xi linear in s (O(h^2));
//   collocation: v and mu not-a-knot cubic splines (numerics/cubic_spline.hpp), Xi cubic Hermite
//   with Xi' = -v mu^T (eq:int-diff-EL's auxiliary, kernels/manifold/scheme.hpp): O(h^4).
// A step whose end the piece does not reach (its difference is no logarithm, manifolds::
// checked_difference: an instance whose logarithm fails between two nodes) is refused by name
// rather than interpolated through the wrong piece. Where difference picks one of several pieces
// (antipodal nodes of the sphere) sol follows the one it picks.
// Compiled in the library for the shipped manifolds (CARTAN_GENERAL_SHIPPED_MANIFOLDS).

#include <string_view>
#include <vector>

#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/principle/vocabulary.hpp"

namespace cartan::general {

/// `x` (the samples of a solution on `manifold` by `method`) at `times`: the solution as a
/// trajectory of the kernel's own type, whose t are `times`. Throws
/// std::invalid_argument "<where>: ..." when x has fewer than 2 samples, a time is outside
/// [t_0, t_M] (NaN included), or the piece of a step does not reach its end node.
template <manifolds::ManifoldWithConnection M>
GeneralTrajectory<M> dense_output(const M& manifold, const GeneralTrajectory<M>& x, Method method,
                                  const std::vector<double>& times, std::string_view where = "dense_output");

}  // namespace cartan::general
