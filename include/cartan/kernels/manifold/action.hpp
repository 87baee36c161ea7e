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

#include <utility>
#include <vector>

#include "cartan/principle/action.hpp"
#include "cartan/principle/manifold_problem.hpp"

namespace cartan::general {

/// Calls add(h_k l_k) for each step of the path through q_0..q_N at the times t (the manifold's
/// piece of principle/action.hpp's rule, the header's comment).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L, class Add>
void for_each_discrete_action_term(const GeneralProblem<M, L>& problem, const std::vector<manifolds::PointOf<M>>& q,
                                   const std::vector<double>& t, Add&& add) {
  const M& m = problem.manifold;
  manifolds::FrameOf<M> frame = problem.initial_frame();
  for_each_action_term(t, [&](std::size_t k, double t_mid, double h) {
    const manifolds::VectorOf<M> d = m.difference(q[k], q[k + 1]);
    const manifolds::VectorOf<M> half = d / 2;
    const manifolds::PointOf<M> mid = m.step(q[k], half);
    const manifolds::FrameOf<M> frame_mid = m.transport_along_step(q[k], half) * frame;
    const manifolds::VectorOf<M> velocity = -m.difference(mid, q[k]) / (h / 2);
    frame = m.transport_along_step(q[k], d) * frame;
    return problem.lagrangian.value(t_mid, mid, manifolds::ComponentsOf<M>(manifolds::dual_frame<M>(frame_mid) * velocity));
  }, std::forward<Add>(add));
}

/// S_h of the path through q_0..q_N at the uniform times k T / N.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
double discrete_action(const GeneralProblem<M, L>& problem, const std::vector<manifolds::PointOf<M>>& q) {
  double action = 0;
  for_each_discrete_action_term(problem, q, uniform_times("discrete_action", problem.T, q.size() - 1),
                                [&](double term) { action += term; });
  return action;
}

/// S_h over the first k steps of the path through q_0..q_N at the times t, k = 0..N (0 first; the
/// last entry is the action).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
std::vector<double> cumulative_discrete_action(const GeneralProblem<M, L>& problem, const std::vector<manifolds::PointOf<M>>& q,
                                               const std::vector<double>& t) {
  std::vector<double> out{0.0};
  out.reserve(q.size());
  for_each_discrete_action_term(problem, q, t, [&](double term) { out.push_back(out.back() + term); });
  return out;
}

/// d/de S_h along q_k -> step(q_k, e w_k) (w_0 = w_N = 0), by a central difference with e = 1e-6
/// (truncation ~ e^2 |S''|, rounding ~ 1e-16 |S| / e).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
double discrete_action_derivative(const GeneralProblem<M, L>& problem, const std::vector<manifolds::PointOf<M>>& q,
                                  const std::vector<manifolds::VectorOf<M>>& w) {
  return action_derivative([&](double eps) {
    std::vector<manifolds::PointOf<M>> p = q;
    for (std::size_t k = 1; k + 1 < p.size(); ++k) p[k] = problem.manifold.step(q[k], manifolds::VectorOf<M>(eps * w[k]));
    return discrete_action(problem, p);
  }, 1e-6);
}

}  // namespace cartan::general
