// Dense output of a sampled solution (transported/dense.hpp), compiled for the shipped groups.
#include "cartan/transported/dense.hpp"

#include <algorithm>

#include "cartan/errors.hpp"
#include "cartan/numerics/cubic_spline.hpp"

namespace cartan::transported {

namespace {

/// The cubic Hermite interpolant on [0, h] at s in [0, 1] with values y0, y1 and derivatives d0, d1.
template <class V>
V hermite(double s, double h, const V& y0, const V& y1, const V& d0, const V& d1) {
  const double s2 = s * s, s3 = s2 * s;
  return ((2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * d1).eval();
}

/// X' of g(t) = g_k exp(X(t)) whose left-trivialised velocity is u: dexp_{-X}^{-1} u by its series
/// u + ad_X u / 2 + ad_X^2 u / 12 (the next term, ad_X^4 u / 720, is O(h^4) on a step).
template <groups::LieGroup G>
groups::TangentOf<G> chart_derivative(const groups::TangentOf<G>& x, const groups::TangentOf<G>& u) {
  const groups::AlgebraMatrixOf<G> ad = G::ad(x);
  const groups::TangentOf<G> adu = ad * u;
  return u + adu / 2 + ad * adu / 12;
}

/// The columns of a list of vectors (n x m).
template <class V>
Eigen::MatrixXd columns(const std::vector<V>& values) {
  Eigen::MatrixXd out(values.empty() ? 0 : values.front().size(), static_cast<Eigen::Index>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) out.col(static_cast<Eigen::Index>(k)) = values[k];
  return out;
}

}  // namespace

template <groups::LieGroup G>
DenseSamples<G> dense_output(const TransportedTrajectory<G>& x, double lambda, Method method, const std::vector<double>& times,
                             std::string_view where) {
  using Tangent = groups::TangentOf<G>;
  const std::size_t m = x.t.size();
  if (m < 2) {
    throw_invalid(where, "the result", std::to_string(m) + " samples", "has nothing to interpolate (it needs at least 2)");
  }
  const double lo = x.t.front(), hi = x.t.back();
  for (double t : times) {
    if (!(t >= lo && t <= hi)) {
      throw_invalid(where, "t", format_value(t), "is outside [0, T] = [" + format_value(lo) + ", " + format_value(hi) + "]");
    }
  }
  const bool collocation = method == Method::Collocation;
  std::vector<Tangent> u;
  numerics::CubicHermite v_spline, mu_spline;
  if (collocation) {
    u = along_transport<G>(lambda, x).u;
    const Eigen::Map<const Eigen::VectorXd> nodes(x.t.data(), static_cast<Eigen::Index>(m));
    v_spline = numerics::not_a_knot_spline(nodes, columns(x.v));
    mu_spline = numerics::not_a_knot_spline(nodes, columns(x.mu));
  }
  DenseSamples<G> out;
  out.g.reserve(times.size()), out.v.reserve(times.size()), out.mu.reserve(times.size()), out.xi.reserve(times.size());
  for (double t : times) {
    const auto upper = static_cast<std::size_t>(std::upper_bound(x.t.begin(), x.t.end(), t) - x.t.begin());
    const std::size_t k = std::clamp<std::size_t>(upper == 0 ? 0 : upper - 1, 0, m - 2);
    const double h = x.t[k + 1] - x.t[k], s = (t - x.t[k]) / h;
    if (s == 0 || s == 1) {  // a node: its sample, exactly
      const std::size_t node = k + (s == 1 ? 1 : 0);
      out.g.push_back(x.g[node]), out.v.push_back(x.v[node]), out.mu.push_back(x.mu[node]), out.xi.push_back(x.xi[node]);
      continue;
    }
    const Tangent step = groups::log_between<G>(x.g[k], x.g[k + 1]);
    Tangent chart;
    if (collocation) {
      chart = hermite<Tangent>(s, h, Tangent::Zero(), step, u[k], chart_derivative<G>(step, u[k + 1]));
      const auto rate = [&](std::size_t i) -> groups::CovectorOf<G> { return -groups::coad<G>(x.v[i], x.mu[i]); };
      out.xi.push_back(hermite<groups::CovectorOf<G>>(s, h, x.xi[k], x.xi[k + 1], rate(k), rate(k + 1)));
      out.v.push_back(v_spline.value_on(static_cast<Eigen::Index>(k), t));
      out.mu.push_back(mu_spline.value_on(static_cast<Eigen::Index>(k), t));
    } else {
      chart = s * step;
      out.xi.push_back((1 - s) * x.xi[k] + s * x.xi[k + 1]);
      out.v.push_back((1 - s) * x.v[k] + s * x.v[k + 1]);
      out.mu.push_back((1 - s) * x.mu[k] + s * x.mu[k + 1]);
    }
    out.g.push_back(G::compose(x.g[k], G::exp(chart)));
  }
  return out;
}

#define CARTAN_TRANSPORTED_DENSE(G)                                                                                  \
  template DenseSamples<G> dense_output<G>(const TransportedTrajectory<G>&, double, Method, const std::vector<double>&, \
                                           std::string_view);
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_TRANSPORTED_DENSE)
#undef CARTAN_TRANSPORTED_DENSE

}  // namespace cartan::transported
