#pragma once
// What every transported-velocity solver returns: a status and diagnostics, never a silent
// trajectory (DESIGN.md "Results, not exceptions, for numerics").

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cartan/kernels/lie_group/method.hpp"
#include "cartan/kernels/lie_group/trajectory.hpp"
#include "cartan/principle/result.hpp"
#include "cartan/status.hpp"

namespace cartan::transported {

using ::cartan::CollocationReport;
using ::cartan::ResultCore;

/// What only the variational integrator reports (variational.hpp): the steps' body velocities
/// u_k = log(g_k^{-1} g_{k+1}) / h and transported velocities v_k = P_k^{-1} u_k (constant on each
/// step; the trajectory's v are their node averages), max_j |G_j| over the interior nodes, and the
/// number of unknowns n (N - 1).
template <groups::LieGroup G>
struct VariationalReport {
  std::vector<groups::TangentOf<G>> step_u, step_v;
  double gradient_norm = 0;
  int unknowns = 0;
};

/// The Lie-group kernel's result (ResultCore, principle/result.hpp): its trajectory and unknowns.
template <groups::LieGroup G>
struct TransportedSolution : ResultCore {
  /// The requested problem's trajectory: at a failure, the best iterate found *for the requested
  /// problem* (never a stage of a continuation at another T or lambda), or empty.
  TransportedTrajectory<G> trajectory;
  groups::TangentOf<G> v0 = groups::TangentOf<G>::Zero();
  groups::CovectorOf<G> xi0 = groups::CovectorOf<G>::Zero();
  std::optional<VariationalReport<G>> variational;  ///< set by the variational integrator only
};

/// What a solution carries besides its samples, one entry per node.
template <groups::LieGroup G>
struct AlongSolution {
  std::vector<groups::AlgebraMatrixOf<G>> P;  ///< Ad(h_k); P_0 = I
  std::vector<groups::TangentOf<G>> u;        ///< P_k v_k, the left-trivialised body velocity g^{-1} g'
  std::vector<double> energy;                 ///< dl/dv(v_k).v_k - l(t_k, g_k, v_k) (lagrangian_energy; = mu_k.v_k by disc-Legendre)
  std::vector<double> action;                 ///< S_h over steps 0..k-1: action[0] = 0, action.back() = S_h
};

}  // namespace cartan::transported
