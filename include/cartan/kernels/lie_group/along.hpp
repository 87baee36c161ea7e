#pragma once
// Quantities along a sampled solution of the transported-velocity problem (eq:reduced-system),
// from the samples alone: the transport operator P_k = Ad(h_k), the body velocity u_k = P_k v_k
// (disc-body-v), the energy E_k = mu_k.v_k - l(t_k, g_k, v_k) (what `cartan verify` checks) and
// the cumulative discrete transported action (kernels/lie_group/action.hpp).
//
// The transport element is rebuilt from consecutive nodes, h_0 = e,
//   h_{k+1} = exp(-lambda log(g_k^{-1} g_{k+1})) h_k          (disc-exp with the step's mean velocity),
// which is exact for both shooting schemes (their steps are g_{k+1} = g_k exp(h u) and
// h_{k+1} = exp(-lambda h u) h_k with the same u: disc-grp, disc-exp and their order-2 form) and
// for the variational integrator, second order in the sample spacing for collocation, and exact
// on H3 (para-trans-Heis: P depends on g - g0 only).

#include <cmath>
#include <limits>
#include <vector>

#include "cartan/kernels/lie_group/action.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/lie_group/scheme.hpp"
#include "cartan/principle/samples.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/transport/disc_exp.hpp"

namespace cartan::transported {

/// h_k (P_k = Ad(h_k)) at every node of the path g[0..M-1] (at least one node); h_0 = e.
template <groups::LieGroup G>
std::vector<groups::ElementOf<G>> transport_elements(double lambda, const std::vector<groups::ElementOf<G>>& g) {
  require_finite(lambda, "transport_elements", "lambda");
  std::vector<groups::ElementOf<G>> h;
  h.reserve(g.size());
  if (g.empty()) return h;
  h.push_back(G::identity());
  for (std::size_t k = 0; k + 1 < g.size(); ++k) {
    h.push_back(transport::disc_exp_update<G>(lambda, 1.0, groups::log_between<G>(g[k], g[k + 1]), h.back()));
  }
  return h;
}

namespace detail {

/// Throws std::invalid_argument unless t, g, v (and mu when `with_mu`) have one entry per node;
/// true when every sample is finite.
template <groups::LieGroup G>
bool check_along(const TransportedTrajectory<G>& x, bool with_mu) {
  // The one check of samples (principle/samples.hpp): sizes only; non-finite samples make NaNs.
  const SampleRules rules{.min_times = 0, .check_times = false, .require_finite = false};
  if (with_mu) {
    return require_samples(x.t, 0, {sample_column("g", x.g), sample_column("v", x.v), sample_column("mu", x.mu)}, rules,
                           "along_solution", "trajectory");
  }
  return require_samples(x.t, 0, {sample_column("g", x.g), sample_column("v", x.v)}, rules, "along_solution",
                         "trajectory");
}

}  // namespace detail

/// P_k and u_k of `x` for the Cartan–Schouten parameter `lambda` (energy and action empty): what
/// needs no model. Throws std::invalid_argument for a non-finite lambda or sizes that differ; with
/// fewer than two samples the lists are empty, and when a sample is not finite every entry is NaN.
template <groups::LieGroup G>
AlongSolution<G> along_transport(double lambda, const TransportedTrajectory<G>& x) {
  require_finite(lambda, "along_solution", "lambda");
  AlongSolution<G> out;
  const std::size_t m = x.g.size();
  const bool finite = detail::check_along(x, false);
  if (m < 2) return out;
  if (!finite) {
    out.P.assign(m, groups::AlgebraMatrixOf<G>::Constant(std::numeric_limits<double>::quiet_NaN()));
    out.u.assign(m, groups::TangentOf<G>::Constant(std::numeric_limits<double>::quiet_NaN()));
    return out;
  }
  const std::vector<groups::ElementOf<G>> h = transport_elements<G>(lambda, x.g);
  for (std::size_t k = 0; k < m; ++k) {
    out.P.push_back(G::Ad(h[k]));
    out.u.push_back(out.P.back() * x.v[k]);
  }
  return out;
}

/// along_transport with the energy E_k and the cumulative S_h for the model `lagrangian`. Throws
/// std::invalid_argument for a non-finite lambda, sizes that differ or times that do not increase;
/// NaN entries and empty lists as along_transport.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
AlongSolution<G> along_solution(const L& lagrangian, double lambda, const TransportedTrajectory<G>& x) {
  AlongSolution<G> out = along_transport<G>(lambda, x);
  const std::size_t m = x.g.size();
  if (m < 2) return out;
  if (!detail::check_along(x, true)) {
    out.energy.assign(m, std::numeric_limits<double>::quiet_NaN());
    out.action.assign(m, std::numeric_limits<double>::quiet_NaN());
    return out;
  }
  out.action = cumulative_transported_action<G>(lagrangian, lambda, x.t, x.g);
  for (std::size_t k = 0; k < m; ++k) {
    out.energy.push_back(mechanics::lagrangian_energy<G>(lagrangian, x.t[k], x.g[k], x.v[k]));
  }
  return out;
}

}  // namespace cartan::transported
