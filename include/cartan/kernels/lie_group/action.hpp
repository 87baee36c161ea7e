#pragma once
// The discrete transported action, an independent check of the integro-differential equation
// (docs/paper-notes.md#independent-checks): the exact solution makes S[g] = int l(t, g, v) dt
// stationary under endpoint-fixed variations. On the piecewise-geodesic path through nodes
// g_0..g_N (u_k = log(g_k^{-1} g_{k+1}) / h on step k) the transport is exact on each step,
// P(t_k + s) = Ad(exp(-lambda s u_k)) P_k (disc-exp), and the transported velocity is
// v = P^{-1} u_k. The midpoint rule then gives a second-order approximation of S,
//   S_h = sum_k h l(t_k + h/2, g_k exp(h u_k / 2), Ad(h_{k+1/2})^{-1} u_k),
// whose derivatives along variations g_k -> g_k exp(e w(t_k)), w(0) = w(T) = 0, vanish as
// h -> 0 at solutions of the paper's equations (at the scheme's order).

#include <string>
#include <string_view>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/principle/action.hpp"
#include "cartan/transport/disc_exp.hpp"

namespace cartan::transported {

namespace detail {

/// Throws std::invalid_argument (naming `where`) for a non-finite lambda, fewer than two nodes,
/// sizes that differ, or times that do not increase.
template <groups::LieGroup G>
void check_action_path(std::string_view where, double lambda, const std::vector<double>& t,
                       const std::vector<groups::ElementOf<G>>& g) {
  require_finite(lambda, where, "lambda");
  if (g.size() < 2) throw_invalid(where, "g.size()", std::to_string(g.size()), "must be at least 2 (one step)");
  if (t.size() != g.size()) {
    throw_invalid(where, "t.size()", std::to_string(t.size()), "must equal g.size() = " + std::to_string(g.size()));
  }
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    if (!(t[k + 1] - t[k] > 0)) throw_invalid(where, "t", format_value(t[k + 1]), "must increase");
  }
}

/// Calls add(h l_k) for each step k of S_h in turn (the midpoint terms above: the Lie group's piece
/// of principle/action.hpp's rule).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L, class Add>
void for_each_action_term(const L& lagrangian, double lambda, const std::vector<double>& t,
                          const std::vector<groups::ElementOf<G>>& g, Add add) {
  groups::ElementOf<G> transport = G::identity();  // h_k with P_k = Ad(h_k)
  cartan::for_each_action_term(t, [&](std::size_t k, double t_mid, double h) {
    const groups::TangentOf<G> u = groups::log_between<G>(g[k], g[k + 1]) / h;
    const groups::ElementOf<G> g_mid = G::compose(g[k], G::exp(groups::TangentOf<G>(h / 2 * u)));
    // (disc-exp) over each half step: exp(-lambda h u) = exp(-lambda (h/2) u)^2 (a one-parameter
    // subgroup), so one exponential serves both halves.
    const groups::ElementOf<G> half_step = transport::disc_exp_update<G>(lambda, h / 2, u, G::identity());
    const groups::ElementOf<G> transport_mid = G::compose(half_step, transport);
    const groups::TangentOf<G> v_mid = G::Ad(G::inverse(transport_mid)) * u;
    transport = G::compose(half_step, transport_mid);
    return lagrangian.value(t_mid, g_mid, v_mid);
  }, add);
}

}  // namespace detail

/// S_h of the path through g[k] at the increasing times t[k] (at least two; steps may differ in
/// length). Throws std::invalid_argument for fewer than two nodes, sizes that differ, times that
/// do not increase, or a non-finite lambda.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
double transported_action(const L& lagrangian, double lambda, const std::vector<double>& t,
                          const std::vector<groups::ElementOf<G>>& g) {
  detail::check_action_path<G>("transported_action", lambda, t, g);
  double action = 0;
  detail::for_each_action_term<G>(lagrangian, lambda, t, g, [&](double term) { action += term; });
  return action;
}

/// S_h over the first k steps, k = 0..N: out[0] = 0 and out[N] = transported_action (the same sum
/// in the same order, so bit-identical). Throws as transported_action.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
std::vector<double> cumulative_transported_action(const L& lagrangian, double lambda, const std::vector<double>& t,
                                                  const std::vector<groups::ElementOf<G>>& g) {
  detail::check_action_path<G>("cumulative_transported_action", lambda, t, g);
  std::vector<double> out{0.0};
  out.reserve(g.size());
  detail::for_each_action_term<G>(lagrangian, lambda, t, g, [&](double term) { out.push_back(out.back() + term); });
  return out;
}

/// S_h of the path through g[0..N] at the uniform times k T / N over [0, T] (N >= 1). Throws
/// std::invalid_argument for fewer than two nodes, a non-finite lambda, or T not positive and finite.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
double transported_action(const L& lagrangian, double lambda, double T, const std::vector<groups::ElementOf<G>>& g) {
  if (g.size() < 2) {
    throw_invalid("transported_action", "g.size()", std::to_string(g.size()), "must be at least 2 (one step)");
  }
  return transported_action<G>(lagrangian, lambda, uniform_times("transported_action", T, g.size() - 1), g);
}

/// d/de S_h(g_k exp(e w_k)) by central differences with step `epsilon` (w_0 = w_N = 0 expected).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
double transported_action_derivative(const L& lagrangian, double lambda, double T,
                                     const std::vector<groups::ElementOf<G>>& g, const std::vector<groups::TangentOf<G>>& w,
                                     double epsilon = 1e-5) {
  if (w.size() != g.size()) {
    throw_invalid("transported_action_derivative", "w.size()", std::to_string(w.size()),
                  "must equal g.size() = " + std::to_string(g.size()));
  }
  require_finite(epsilon, "transported_action_derivative", "epsilon");
  if (!(epsilon > 0)) throw_invalid("transported_action_derivative", "epsilon", format_value(epsilon), "must be positive");
  return action_derivative([&](double e) {
    std::vector<groups::ElementOf<G>> out(g.size());
    for (std::size_t k = 0; k < g.size(); ++k) out[k] = G::compose(g[k], G::exp(groups::TangentOf<G>(e * w[k])));
    return transported_action<G>(lagrangian, lambda, T, out);
  }, epsilon);
}

}  // namespace cartan::transported
