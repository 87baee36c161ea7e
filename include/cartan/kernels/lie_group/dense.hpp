#pragma once
// Dense output: a sampled solution of the transported-velocity problem at any time in [t_0, t_M]
// (SolveResult.sol in Python, `cartan solve --samples` for every method). At a node it is the
// sample itself. On the step [t_k, t_k+1], s = (t - t_k) / h, with X_k = log(g_k^{-1} g_k+1):
//   the discrete schemes (shooting, two-level, multiple shooting, variational):
//     g(t) = g_k exp(s X_k), the one-parameter subgroup through both nodes along which the
//     Lie–Euler and RKMK steps (disc-grp) move, O(h^2) from the smooth solution, on the group;
//     v, mu, xi linear in s (O(h^2));
//   collocation (its samples are the continuous solution's):
//     g(t) = g_k exp(X(t)), X the cubic Hermite interpolant from 0 to X_k with X'(t_k) = u_k and
//     X'(t_k+1) = dexp_{-X_k}^{-1} u_k+1 (the series u + ad_X u / 2 + ad_X^2 u / 12; the next term is
//     O(h^4)), u = P v the body velocity (disc-body-v, along.hpp): O(h^3);
//     xi cubic Hermite with xi' = -ad*_v mu (disc-aux); v and mu not-a-knot cubic splines
//     (numerics/cubic_spline.hpp): O(h^4).
// Compiled in the library for the shipped groups (CARTAN_TRANSPORTED_SHIPPED_GROUPS).

#include <string_view>
#include <vector>

#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/lie_group/method.hpp"
#include "cartan/kernels/lie_group/trajectory.hpp"

namespace cartan::transported {

/// `x` (the samples of a solution by `method`, with its lambda) at `times`: the solution as a
/// trajectory of the kernel's own type, whose t are `times`. Throws
/// std::invalid_argument "<where>: ..." when x has fewer than 2 samples or a time is outside
/// [t_0, t_M] (NaN included).
template <groups::LieGroup G>
TransportedTrajectory<G> dense_output(const TransportedTrajectory<G>& x, double lambda, Method method,
                                      const std::vector<double>& times, std::string_view where = "dense_output");

}  // namespace cartan::transported
