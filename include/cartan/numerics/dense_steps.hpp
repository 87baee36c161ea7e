#pragma once
// What the dense outputs of both kernels' results share (kernels/lie_group/dense.hpp, kernels/manifold/dense.hpp):
// checking the requested times against the nodes, finding a time's step, the cubic Hermite weights
// and a list of vectors as the columns the splines take (numerics/cubic_spline.hpp).

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/errors.hpp"

namespace cartan::numerics {

/// How far past an end of [t_0, t_M] a requested time may lie, relative to the larger end: a few
/// roundings (T * (1 + 1e-15), a time computed as a sum of steps), read as the end itself.
inline constexpr double kDenseEndSlack = 16 * std::numeric_limits<double>::epsilon();

/// Throws std::invalid_argument "<where>: ..." unless there are at least 2 nodes and every time
/// lies in [nodes.front(), nodes.back()] up to kDenseEndSlack (NaN does not).
inline void check_dense_times(const std::vector<double>& nodes, const std::vector<double>& times, std::string_view where) {
  if (nodes.size() < 2) {
    throw_invalid(where, "the result", std::to_string(nodes.size()) + " samples", "has nothing to interpolate (it needs at least 2)");
  }
  const double lo = nodes.front(), hi = nodes.back();
  const double slack = kDenseEndSlack * std::max(std::abs(lo), std::abs(hi));
  for (double t : times) {
    if (!(t >= lo - slack && t <= hi + slack)) {
      throw_invalid(where, "t", format_value(t), "is outside [0, T] = [" + format_value(lo) + ", " + format_value(hi) + "]");
    }
  }
}

/// Where a time in [t_0, t_M] lies: on step k (0 <= k <= M - 1) at s = (t - t_k) / h in [0, 1].
struct DenseStep {
  std::size_t k = 0;
  double s = 0, h = 0;
  /// At a node (s = 0 or 1) the dense outputs return the sample itself, exactly: its index.
  bool at_node() const { return s == 0 || s == 1; }
  std::size_t node() const { return k + (s == 1 ? 1 : 0); }
  /// The straight line from a (s = 0) to b (s = 1).
  template <class V>
  V linear(const V& a, const V& b) const {
    return ((1 - s) * a + s * b).eval();
  }
};

/// The step of t, a time check_dense_times accepted (one within kDenseEndSlack of an end is that end).
inline DenseStep locate_dense_step(const std::vector<double>& nodes, double t) {
  t = std::clamp(t, nodes.front(), nodes.back());
  const auto upper = static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end(), t) - nodes.begin());
  const std::size_t k = std::clamp<std::size_t>(upper == 0 ? 0 : upper - 1, 0, nodes.size() - 2);
  const double h = nodes[k + 1] - nodes[k];
  return {k, (t - nodes[k]) / h, h};
}

/// The cubic Hermite interpolant on [0, h] at s in [0, 1] with values y0, y1 and derivatives d0, d1
/// (the basis of cubic_hermite.hpp).
template <class V>
V hermite_at(double s, double h, const V& y0, const V& y1, const V& d0, const V& d1) {
  const double s2 = s * s, s3 = s2 * s;
  return ((2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * d1).eval();
}

/// The columns of a list of vectors (n x m).
template <class V>
Eigen::MatrixXd as_columns(const std::vector<V>& values) {
  Eigen::MatrixXd out(values.empty() ? 0 : values.front().size(), static_cast<Eigen::Index>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) out.col(static_cast<Eigen::Index>(k)) = values[k];
  return out;
}

}  // namespace cartan::numerics
