#pragma once
// Quantities along a sampled solution of the general problem, from the samples alone (the
// counterpart of kernels/lie_group/along.hpp): the parallel frame E_k, the represented velocity
// u_k = E_k v_k (q' = u), the energy E_k = mu(v_k).v_k - l(t_k, q_k, v_k) (conserved for every
// connection when l does not depend on t: docs/general-connections.md#energy; what verify checks)
// and the cumulative discrete transported action (action.hpp).
//
// The frame is the trajectory's own where it has one at every node (a solve's: its scheme's or
// collocation's transported frame), else rebuilt from consecutive nodes, E_0 = the problem's
// initial frame and
//   E_{k+1} = transport_along_step(q_k, difference(q_k, q_{k+1})) E_k,
// exact for both shooting schemes (their steps are such pieces) and second order in the sample
// spacing for collocation (its frame solves e' = -Gamma(q', e) along the smooth path).

#include <limits>
#include <string>
#include <vector>

#include "cartan/kernels/manifold/action.hpp"
#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/principle/samples.hpp"

namespace cartan::general {

/// E_k at every node of the path q[0..M-1] (the header's rule); empty for no nodes.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
std::vector<manifolds::FrameOf<M>> transported_frames(const GeneralProblem<M, L>& problem,
                                                      const std::vector<manifolds::PointOf<M>>& q) {
  std::vector<manifolds::FrameOf<M>> frame;
  if (q.empty()) return frame;
  frame.reserve(q.size());
  frame.push_back(problem.initial_frame());
  for (std::size_t k = 0; k + 1 < q.size(); ++k) {
    frame.push_back(problem.manifold.transport_along_step(q[k], problem.manifold.difference(q[k], q[k + 1])) * frame.back());
  }
  return frame;
}

/// Throws std::invalid_argument "along_general: ..." unless q and v have one entry per time and
/// the times increase from 0 to T (require_sample_times, to a hundredth of a step); returns whether
/// every time, q and v is finite.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
bool check_along_general(const GeneralProblem<M, L>& problem, const GeneralTrajectory<M>& x) {
  const std::size_t n = x.t.size();
  const SampleRules rules{.min_times = 0, .time_tolerance = n >= 2 ? 0.01 / static_cast<double>(n - 1) : 0.0,
                          .require_finite = false};
  return require_samples(x.t, problem.T, {sample_column("q", x.q), sample_column("v", x.v)}, rules,
                         "along_general", "trajectory");
}

/// The frames (x's own, or rebuilt: the header's comment), u, energy and cumulative S_h (0 at the
/// first node; the last entry is the action) of `x` as a solution of `problem`, at x's own times. Throws
/// std::invalid_argument as check_along_general; with fewer than two samples every list is empty,
/// and where a sample is not finite energy and action are NaN.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralAlong<M> along_general(const GeneralProblem<M, L>& problem, const GeneralTrajectory<M>& x) {
  const bool finite = check_along_general(problem, x);
  GeneralAlong<M> out;
  const std::size_t n = x.t.size();
  if (n < 2) return out;
  if (!finite) {
    out.energy.assign(n, std::numeric_limits<double>::quiet_NaN());
    out.action.assign(n, std::numeric_limits<double>::quiet_NaN());
    return out;
  }
  out.frame = x.frame.size() == n ? x.frame : transported_frames(problem, x.q);  // a solve's own, or rebuilt
  for (std::size_t k = 0; k < n; ++k) {
    out.u.push_back(out.frame[k] * x.v[k]);
    const manifolds::ComponentsOf<M> mu = problem.lagrangian.momentum(x.t[k], x.q[k], x.v[k]);
    out.energy.push_back(mu.dot(x.v[k]) - problem.lagrangian.value(x.t[k], x.q[k], x.v[k]));
  }
  out.action = cumulative_discrete_action(problem, x.q, x.t);
  return out;
}

}  // namespace cartan::general
