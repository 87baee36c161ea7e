#pragma once
// The discrete transported action of the general problem, an independent check of its
// equations (docs/general-connections.md#verification): through the nodes q_0..q_N at uniform
// step h, the curve made of the instance's pieces s -> step(q_k, s d_k), d_k = difference(q_k,
// q_{k+1}), with the frame transported exactly along each piece (transport_along_step), and the
// midpoint rule
//   S_h = sum_k h l(t_k + h/2, m_k, E(m_k)^+ c_k'),   m_k = step(q_k, d_k / 2),
// where c_k' = -difference(m_k, q_k) / (h / 2) is the piece's represented velocity at its midpoint
// (exact for pieces that retrace themselves: chart lines, geodesics of S^2 and H^2, g exp(s x)).
// Its derivatives along endpoint-fixed variations vanish as h -> 0 at solutions of the problem, at
// the scheme's order; nothing of the scheme is used.

#include <vector>

#include "cartan/general/problem.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
double discrete_action(const GeneralProblem<M, L>& problem, const std::vector<manifolds::PointOf<M>>& q) {
  const double h = problem.T / static_cast<double>(q.size() - 1);
  const M& m = problem.manifold;
  manifolds::FrameOf<M> frame = problem.initial_frame();
  double action = 0;
  for (std::size_t k = 0; k + 1 < q.size(); ++k) {
    const manifolds::VectorOf<M> d = m.difference(q[k], q[k + 1]);
    const manifolds::VectorOf<M> half = d / 2;
    const manifolds::PointOf<M> mid = m.step(q[k], half);
    const manifolds::FrameOf<M> frame_mid = m.transport_along_step(q[k], half) * frame;
    const manifolds::VectorOf<M> velocity = -m.difference(mid, q[k]) / (h / 2);
    const manifolds::ComponentsOf<M> v = manifolds::dual_frame<M>(frame_mid) * velocity;
    action += h * problem.lagrangian.value((static_cast<double>(k) + 0.5) * h, mid, v);
    frame = m.transport_along_step(q[k], d) * frame;
  }
  return action;
}

/// d/de S_h along q_k -> step(q_k, e w_k) (w_0 = w_N = 0), by a central difference with e = 1e-6
/// (truncation ~ e^2 |S''|, rounding ~ 1e-16 |S| / e).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
double discrete_action_derivative(const GeneralProblem<M, L>& problem, const std::vector<manifolds::PointOf<M>>& q,
                                  const std::vector<manifolds::VectorOf<M>>& w) {
  const double e = 1e-6;
  auto varied = [&](double eps) {
    std::vector<manifolds::PointOf<M>> p = q;
    for (std::size_t k = 1; k + 1 < p.size(); ++k) p[k] = problem.manifold.step(q[k], manifolds::VectorOf<M>(eps * w[k]));
    return discrete_action(problem, p);
  };
  return (varied(e) - varied(-e)) / (2 * e);
}

}  // namespace cartan::general
