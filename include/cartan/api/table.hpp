#pragma once
// The api's tables of numbers (api::Samples, api::Along): one row per time, row-major, and the
// fixed-size values (a point, an element, a frame) read back from a row or from a list of numbers.
// Eigen only, so that the bindings' conversions (python/src/convert.hpp) share the type.

#include <Eigen/Core>
#include <vector>

namespace cartan::api {

/// One row per time, stored row-major: a row's numbers are contiguous, as a sample's are in the
/// kernels and in NumPy, so that a table is written, read and handed to NumPy in one pass.
using Table = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Row k of a table as the fixed-size value it holds (a point, an element, a frame: row-major
/// within the row, as models::element_numbers writes it).
template <class Value, class Rows>
Value value_of_row(const Rows& rows, Eigen::Index k) {
  Value x;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) x(i, j) = rows(k, i * x.cols() + j);
  }
  return x;
}

/// The value whose numbers (row-major, models::element_numbers) these are, as written: not
/// projected, no count checked (the caller's).
template <class Value>
Value value_of_numbers(const std::vector<double>& numbers) {
  return value_of_row<Value>(Eigen::Map<const Table>(numbers.data(), 1, static_cast<Eigen::Index>(numbers.size())), 0);
}

}  // namespace cartan::api
