#pragma once
// Samples in numbers (api/solve.hpp) and the kernels' trajectories, each as the other, with the one
// check of their tables' shapes: what the api's doors share (solve.cpp, verify.cpp, dense.cpp).
// Private to src/api/.

#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "cartan/api/solve.hpp"
#include "cartan/kernels/lie_group/solution.hpp"
#include "cartan/kernels/lie_group/trajectory.hpp"
#include "cartan/kernels/manifold/solution.hpp"

namespace cartan::api::detail {

/// One row per value: its numbers (models::element_numbers: a matrix row-major, a vector as it is).
template <class Value>
Table rows(const std::vector<Value>& values) {
  if (values.empty()) return {};
  const Eigen::Index rows = values.front().rows(), cols = values.front().cols();
  Table out(static_cast<Eigen::Index>(values.size()), rows * cols);
  for (std::size_t k = 0; k < values.size(); ++k) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      for (Eigen::Index j = 0; j < cols; ++j) out(static_cast<Eigen::Index>(k), i * cols + j) = values[k](i, j);
    }
  }
  return out;
}

/// Throws "<where>: samples.<name> = (r x c numbers) must have <rows> rows (one per time) of <width>
/// numbers" unless `table` has one row per time of x and `width` columns, or (where `optional`)
/// no rows.
void check_table(const Samples& x, const Table& table, const char* name, Eigen::Index width, std::string_view where,
                 bool optional = false);
/// check_table of each table of x: points of `point_size` numbers, v and mu of n, the auxiliary of
/// `aux_width`, and (where `frame_size` > 0) frames of `frame_size`.
void check_samples(const Samples& x, Eigen::Index point_size, Eigen::Index n, Eigen::Index aux_width, std::string_view where,
                   Eigen::Index frame_size = 0);

/// A kernel's trajectory as rows of numbers (Samples), and back. The rows are read as the
/// values they write, not projected (the checks see the data); a general trajectory's frames only
/// where the samples have them.
template <groups::LieGroup G>
Samples samples_of(const transported::TransportedTrajectory<G>& x) {
  return {Eigen::Map<const Eigen::VectorXd>(x.t.data(), static_cast<Eigen::Index>(x.t.size())), rows(x.g), {}, rows(x.v),
          rows(x.mu), rows(x.xi)};
}
template <manifolds::ManifoldWithConnection M>
Samples samples_of(const general::GeneralTrajectory<M>& x) {
  return {Eigen::Map<const Eigen::VectorXd>(x.t.data(), static_cast<Eigen::Index>(x.t.size())), rows(x.q), rows(x.frame),
          rows(x.v), rows(x.mu), rows(x.Xi)};
}
/// Each row of `table` as a Value, where it has one row per time (else none: an optional table).
template <class Value>
std::vector<Value> values_of(const Table& table, Eigen::Index times) {
  std::vector<Value> out;
  if (table.rows() != times) return out;
  out.reserve(static_cast<std::size_t>(times));
  for (Eigen::Index k = 0; k < times; ++k) out.push_back(value_of_row<Value>(table, k));
  return out;
}
template <groups::LieGroup G>
transported::TransportedTrajectory<G> lie_trajectory(const Samples& x) {
  const Eigen::Index m = x.t.size();
  return {{x.t.data(), x.t.data() + m}, values_of<groups::ElementOf<G>>(x.points, m), values_of<groups::TangentOf<G>>(x.v, m),
          values_of<groups::CovectorOf<G>>(x.mu, m), values_of<groups::CovectorOf<G>>(x.aux, m)};
}
template <manifolds::ManifoldWithConnection M>
general::GeneralTrajectory<M> general_trajectory(const Samples& x) {
  const Eigen::Index m = x.t.size();
  return {{x.t.data(), x.t.data() + m}, values_of<manifolds::PointOf<M>>(x.points, m), values_of<manifolds::FrameOf<M>>(x.frames, m),
          values_of<manifolds::ComponentsOf<M>>(x.v, m), values_of<manifolds::ComponentsOf<M>>(x.mu, m),
          values_of<manifolds::ComponentMatrixOf<M>>(x.aux, m)};
}

/// What a kernel computes along a solution (along.hpp) as rows of numbers.
template <groups::LieGroup G>
Along along_of(const transported::AlongSolution<G>& a) {
  return {rows(a.P), rows(a.u), Eigen::Map<const Eigen::VectorXd>(a.energy.data(), static_cast<Eigen::Index>(a.energy.size())),
          Eigen::Map<const Eigen::VectorXd>(a.action.data(), static_cast<Eigen::Index>(a.action.size()))};
}
template <manifolds::ManifoldWithConnection M>
Along along_of(const general::GeneralAlong<M>& a) {
  return {rows(a.frame), rows(a.u), Eigen::Map<const Eigen::VectorXd>(a.energy.data(), static_cast<Eigen::Index>(a.energy.size())),
          Eigen::Map<const Eigen::VectorXd>(a.action.data(), static_cast<Eigen::Index>(a.action.size()))};
}

}  // namespace cartan::api::detail
