#pragma once
// Samples in numbers (api/solve.hpp) and the kernels' trajectories, each as the other, with the one
// check of their tables' shapes: what the api's doors share (solve.cpp, verify.cpp, dense.cpp).
// Private to src/api/.

#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "cartan/api/solve.hpp"
#include "cartan/kernels/lie_group/trajectory.hpp"
#include "cartan/kernels/manifold/solution.hpp"

namespace cartan::api::detail {

/// One row per value: its numbers (models::element_numbers: a matrix row-major, a vector as it is).
template <class Value>
Eigen::MatrixXd rows(const std::vector<Value>& values) {
  if (values.empty()) return {};
  const Eigen::Index rows = values.front().rows(), cols = values.front().cols();
  Eigen::MatrixXd out(static_cast<Eigen::Index>(values.size()), rows * cols);
  for (std::size_t k = 0; k < values.size(); ++k) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      for (Eigen::Index j = 0; j < cols; ++j) out(static_cast<Eigen::Index>(k), i * cols + j) = values[k](i, j);
    }
  }
  return out;
}

/// Row k of `rows` as a Value of the given shape (read row-major, as rows() writes it).
template <class Value>
Value value_of_row(const Eigen::MatrixXd& rows, Eigen::Index k) {
  Value x;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) x(i, j) = rows(k, i * x.cols() + j);
  }
  return x;
}

/// Throws "<where>: samples.<name> = (r x c numbers) must have <rows> rows (one per time) of <width>
/// numbers" unless each table of x has one row per time: points of `point_size` numbers, v and mu
/// of n, the auxiliary of `aux_width`, and (where `frame_size` > 0) frames of `frame_size`.
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
template <groups::LieGroup G>
transported::TransportedTrajectory<G> lie_trajectory(const Samples& x) {
  transported::TransportedTrajectory<G> out;
  out.t.assign(x.t.data(), x.t.data() + x.t.size());
  for (Eigen::Index k = 0; k < x.t.size(); ++k) {
    out.g.push_back(value_of_row<groups::ElementOf<G>>(x.points, k));
    out.v.push_back(value_of_row<groups::TangentOf<G>>(x.v, k));
    out.mu.push_back(value_of_row<groups::CovectorOf<G>>(x.mu, k));
    out.xi.push_back(value_of_row<groups::CovectorOf<G>>(x.aux, k));
  }
  return out;
}
template <manifolds::ManifoldWithConnection M>
general::GeneralTrajectory<M> general_trajectory(const Samples& x) {
  general::GeneralTrajectory<M> out;
  out.t.assign(x.t.data(), x.t.data() + x.t.size());
  const bool frames = x.frames.rows() == x.t.size() && x.t.size() > 0;
  for (Eigen::Index k = 0; k < x.t.size(); ++k) {
    out.q.push_back(value_of_row<manifolds::PointOf<M>>(x.points, k));
    if (frames) out.frame.push_back(value_of_row<manifolds::FrameOf<M>>(x.frames, k));
    out.v.push_back(value_of_row<manifolds::ComponentsOf<M>>(x.v, k));
    out.mu.push_back(value_of_row<manifolds::ComponentsOf<M>>(x.mu, k));
    out.Xi.push_back(value_of_row<manifolds::ComponentMatrixOf<M>>(x.aux, k));
  }
  return out;
}

}  // namespace cartan::api::detail
