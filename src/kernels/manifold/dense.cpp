// Dense output of a general solution (kernels/manifold/dense.hpp), compiled for the shipped manifolds.
#include "cartan/kernels/manifold/dense.hpp"

#include <algorithm>

#include "cartan/errors.hpp"
#include "cartan/numerics/cubic_spline.hpp"
#include "cartan/numerics/dense_steps.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M>
GeneralTrajectory<M> dense_output(const M& manifold, const GeneralTrajectory<M>& x, cartan::Method method,
                                  const std::vector<double>& times, std::string_view where) {
  using Matrix = manifolds::ComponentMatrixOf<M>;
  numerics::check_dense_times(x.t, times, where);
  const std::size_t m = x.t.size();
  const bool collocation = method == cartan::Method::Collocation;
  numerics::CubicHermite v_spline, mu_spline;
  if (collocation) {
    const Eigen::Map<const Eigen::VectorXd> nodes(x.t.data(), static_cast<Eigen::Index>(m));
    v_spline = numerics::not_a_knot_spline(nodes, numerics::as_columns(x.v));
    mu_spline = numerics::not_a_knot_spline(nodes, numerics::as_columns(x.mu));
  }
  GeneralTrajectory<M> out;
  out.t = times;
  for (double t : times) {
    const numerics::DenseStep place = numerics::locate_dense_step(x.t, t);
    const auto [k, s, h] = place;
    if (place.at_node()) {
      const std::size_t node = place.node();
      out.q.push_back(x.q[node]), out.frame.push_back(x.frame[node]), out.v.push_back(x.v[node]);
      out.mu.push_back(x.mu[node]), out.Xi.push_back(x.Xi[node]);
      continue;
    }
    const manifolds::CheckedDifference<M> piece = manifolds::checked_difference(manifold, x.q[k], x.q[k + 1]);
    if (!piece.reaches) {
      throw_invalid(where, "t", format_value(t),
                    "lies on the step from t = " + format_value(x.t[k]) + " to " + format_value(x.t[k + 1]) +
                        ", whose end the manifold's piece does not reach (a cut locus between two nodes)");
    }
    const manifolds::VectorOf<M> partial = s * piece.x;
    out.q.push_back(manifold.step(x.q[k], partial));
    out.frame.push_back(manifold.transport_along_step(x.q[k], partial) * x.frame[k]);
    if (collocation) {
      const auto index = static_cast<Eigen::Index>(k);
      out.v.push_back(v_spline.value_on(index, t));
      out.mu.push_back(mu_spline.value_on(index, t));
      const Matrix d0 = -x.v[k] * x.mu[k].transpose(), d1 = -x.v[k + 1] * x.mu[k + 1].transpose();  // Xi' = -v mu^T
      out.Xi.push_back(numerics::hermite_at<Matrix>(s, h, x.Xi[k], x.Xi[k + 1], d0, d1));
    } else {
      out.v.push_back(place.linear(x.v[k], x.v[k + 1]));
      out.mu.push_back(place.linear(x.mu[k], x.mu[k + 1]));
      out.Xi.push_back(place.linear(x.Xi[k], x.Xi[k + 1]));
    }
  }
  return out;
}

#define CARTAN_GENERAL_DENSE(M)                                                                  \
  template GeneralTrajectory<M> dense_output<M>(const M&, const GeneralTrajectory<M>&, cartan::Method, \
                                                const std::vector<double>&, std::string_view);
CARTAN_GENERAL_SHIPPED_MANIFOLDS(CARTAN_GENERAL_DENSE)
#undef CARTAN_GENERAL_DENSE

}  // namespace cartan::general
