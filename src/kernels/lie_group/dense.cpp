// Dense output of a sampled solution (kernels/lie_group/dense.hpp), compiled for the shipped groups.
#include "cartan/kernels/lie_group/dense.hpp"

#include <algorithm>

#include "cartan/errors.hpp"
#include "cartan/numerics/cubic_spline.hpp"
#include "cartan/numerics/dense_steps.hpp"

namespace cartan::transported {

namespace {

/// X' of g(t) = g_k exp(X(t)) whose left-trivialised velocity is u: dexp_{-X}^{-1} u by its series
/// u + ad_X u / 2 + ad_X^2 u / 12 (the next term, ad_X^4 u / 720, is O(h^4) on a step).
template <groups::LieGroup G>
groups::TangentOf<G> chart_derivative(const groups::TangentOf<G>& x, const groups::TangentOf<G>& u) {
  const groups::AlgebraMatrixOf<G> ad = G::ad(x);
  const groups::TangentOf<G> adu = ad * u;
  return u + adu / 2 + ad * adu / 12;
}

}  // namespace

template <groups::LieGroup G>
TransportedTrajectory<G> dense_output(const TransportedTrajectory<G>& x, double lambda, Method method,
                                      const std::vector<double>& times, std::string_view where) {
  using Tangent = groups::TangentOf<G>;
  numerics::check_dense_times(x.t, times, where);
  const std::size_t m = x.t.size();
  const bool collocation = method == Method::Collocation;
  std::vector<Tangent> u;
  numerics::CubicHermite v_spline, mu_spline;
  if (collocation) {
    u = along_transport<G>(lambda, x).u;
    const Eigen::Map<const Eigen::VectorXd> nodes(x.t.data(), static_cast<Eigen::Index>(m));
    v_spline = numerics::not_a_knot_spline(nodes, numerics::as_columns(x.v));
    mu_spline = numerics::not_a_knot_spline(nodes, numerics::as_columns(x.mu));
  }
  TransportedTrajectory<G> out;
  out.reserve(times.size());
  out.t = times;
  for (double t : times) {
    const numerics::DenseStep place = numerics::locate_dense_step(x.t, t);
    const auto [k, s, h] = place;
    if (place.at_node()) {
      const std::size_t node = place.node();
      out.g.push_back(x.g[node]), out.v.push_back(x.v[node]), out.mu.push_back(x.mu[node]), out.xi.push_back(x.xi[node]);
      continue;
    }
    const Tangent step = groups::log_between<G>(x.g[k], x.g[k + 1]);
    Tangent chart;
    if (collocation) {
      chart = numerics::hermite_at<Tangent>(s, h, Tangent::Zero(), step, u[k], chart_derivative<G>(step, u[k + 1]));
      const auto rate = [&](std::size_t i) -> groups::CovectorOf<G> { return -groups::coad<G>(x.v[i], x.mu[i]); };
      out.xi.push_back(numerics::hermite_at<groups::CovectorOf<G>>(s, h, x.xi[k], x.xi[k + 1], rate(k), rate(k + 1)));
      out.v.push_back(v_spline.value_on(static_cast<Eigen::Index>(k), t));
      out.mu.push_back(mu_spline.value_on(static_cast<Eigen::Index>(k), t));
    } else {
      chart = s * step;
      out.xi.push_back(place.linear(x.xi[k], x.xi[k + 1]));
      out.v.push_back(place.linear(x.v[k], x.v[k + 1]));
      out.mu.push_back(place.linear(x.mu[k], x.mu[k + 1]));
    }
    out.g.push_back(G::compose(x.g[k], G::exp(chart)));
  }
  return out;
}

#define CARTAN_TRANSPORTED_DENSE(G)                                                                         \
  template TransportedTrajectory<G> dense_output<G>(const TransportedTrajectory<G>&, double, Method,       \
                                                    const std::vector<double>&, std::string_view);
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_TRANSPORTED_DENSE)
#undef CARTAN_TRANSPORTED_DENSE

}  // namespace cartan::transported
