#pragma once
// The quadrics of quadric.hpp (S^2, K = 1; H^2, K = -1) in the stereographic chart from the point
// (0, 0, -1): x = (q1, q2) / (1 + q3), with inverse q = (2 x, 1 - K |x|^2) / (1 + K |x|^2). The
// chart covers S^2 minus (0, 0, -1) (all of R^2) and H^2 (the Poincare disc |x| < 1). The metric
// <., .> of the quadric pulls back to the conformal metric g = e^(2 phi) I with
// e^phi = 2 / (1 + K |x|^2), whose Levi-Civita connection is
//   Gamma^k_ij = delta^k_i phi_j + delta^k_j phi_i - delta_ij phi_k,  phi_j = -2 K x_j / (1 + K |x|^2).
// For coordinate-wise methods (kernels/manifold/hamilton.hpp) on the quadrics; tests/general checks that
// these symbols are the quadric's connection (quadric.hpp) pulled back.

#include <cmath>
#include <limits>

#include "cartan/manifolds/chart.hpp"

namespace cartan::manifolds {

/// The chart point of a quadric point q (1 + q3 > 0).
inline Eigen::Vector2d stereographic(const Eigen::Vector3d& q) { return q.head<2>() / (1 + q.z()); }

/// The quadric point of a chart point x (K = +-1).
template <int Curvature>
Eigen::Vector3d from_stereographic(const Eigen::Vector2d& x) {
  static_assert(Curvature == 1 || Curvature == -1);
  const double r2 = Curvature * x.squaredNorm();
  return Eigen::Vector3d(2 * x.x(), 2 * x.y(), 1 - r2) / (1 + r2);
}

/// The chart components of a tangent vector u at the quadric point q: d stereographic(q)[u].
inline Eigen::Vector2d stereographic_velocity(const Eigen::Vector3d& q, const Eigen::Vector3d& u) {
  const double s = 1 + q.z();
  return u.head<2>() / s - q.head<2>() * (u.z() / (s * s));
}

/// The quadric's Levi-Civita connection and metric in the stereographic chart (header comment).
/// Chart points outside the domain (|x| >= 1 on H^2) give non-finite symbols, which the chart's
/// `validate` rejects.
template <int Curvature>
Chart<2> stereographic_chart() {
  static_assert(Curvature == 1 || Curvature == -1);
  constexpr double K = Curvature;
  const auto conformal_factor = [](const Eigen::Vector2d& x) {
    const double d = 1 + K * x.squaredNorm();
    return d > 0 ? 2 / d : std::numeric_limits<double>::quiet_NaN();
  };
  const auto symbols = [conformal_factor](const Eigen::Vector2d& x) {
    const double f = conformal_factor(x);
    const Eigen::Vector2d dphi = -K * f * x;  // phi_j = -2 K x_j / (1 + K |x|^2)
    Chart<2>::Coefficients c;
    for (int i = 0; i < 2; ++i) {
      c[i].setZero();
      for (int k = 0; k < 2; ++k) {
        for (int j = 0; j < 2; ++j) c[i](k, j) = (k == i) * dphi[j] + (k == j) * dphi[i] - (i == j) * dphi[k];
      }
    }
    return c;
  };
  const auto metric = [conformal_factor](const Eigen::Vector2d& x) -> Eigen::Matrix2d {
    const double f = conformal_factor(x);
    return f * f * Eigen::Matrix2d::Identity();
  };
  return Chart<2>(symbols, metric, Curvature > 0 ? "sphere-stereographic" : "poincare-disc", true);
}

}  // namespace cartan::manifolds
