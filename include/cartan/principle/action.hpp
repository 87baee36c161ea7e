#pragma once
// The discrete transported action's midpoint rule, written once for every kernel
// (docs/paper-notes.md#independent-checks, docs/general-connections.md#verification): on the path
// made of the kernel's pieces through the nodes x_0..x_N at the times t_k,
//   S_h = sum_k h_k l(t_k + h_k/2, x_k+1/2, v_k+1/2),   h_k = t_k+1 - t_k,
// where the kernel's piece of step k gives its midpoint x_k+1/2, the transported velocity there
// and the transport carried over the step (kernels/lie_group/action.hpp: the half-step exponential on a
// Lie group; kernels/manifold/action.hpp: the manifold's step and transport_along_step). Its derivatives
// along endpoint-fixed variations vanish as h -> 0 at solutions, at the scheme's order.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/principle/horizon.hpp"

namespace cartan {

/// Calls add(h_k l_k) for each step k of the path through the times t, in order:
/// `midpoint_value(k, t_k + h_k / 2, h_k)` is l at step k's midpoint (it advances the kernel's
/// transport over the step).
template <class MidpointValue, class Add>
void for_each_action_term(const std::vector<double>& t, MidpointValue&& midpoint_value, Add&& add) {
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double h = t[k + 1] - t[k];
    add(h * midpoint_value(k, t[k] + h / 2, h));
  }
}

/// The uniform times k T / steps, k = 0..steps; throws std::invalid_argument (naming `where`)
/// unless T is positive and finite.
inline std::vector<double> uniform_times(std::string_view where, double T, std::size_t steps) {
  require_horizon(T, 1, where);  // T alone: the steps are the caller's
  std::vector<double> t(steps + 1);
  for (std::size_t k = 0; k <= steps; ++k) t[k] = T * static_cast<double>(k) / static_cast<double>(steps);
  return t;
}

/// The derivative of an action along a variation, d/de S(e) at e = 0, by the five-point central
/// difference (8 (S(e) - S(-e)) - (S(2e) - S(-2e))) / (12 e): truncation ~ e^4 |S^(5)| / 30,
/// rounding ~ 2e-16 |S| / e. (The three-point one's truncation, e^2 |S'''| / 6, is an absolute
/// error: at e = 1e-6 about 4e-13 on a curved manifold, the whole first variation of a path 1e-9
/// long, so verify's stationarity failed such paths.)
template <class ActionAlong>
double action_derivative(ActionAlong&& action_along, double e) {
  const double near = action_along(e) - action_along(-e), far = action_along(2 * e) - action_along(-2 * e);
  return (8 * near - far) / (12 * e);
}

}  // namespace cartan
