#pragma once
// NumPy <-> Eigen for the bindings. Inputs are taken as Python objects and converted here, so
// that a wrong shape raises ValueError (std::invalid_argument) naming the argument, in the
// library's message format "<where>: <name> = <value> <problem>", rather than pybind11's
// TypeError about overloads. Outputs are fresh NumPy arrays: vectors 1-D, matrices 2-D
// (row-major, as docs/conventions.md), sequences of them stacked along a new first axis (a sequence
// given as an rvalue becomes the array's storage, without a copy).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "cartan/api/table.hpp"
#include "cartan/errors.hpp"

namespace cartan::python {

namespace py = pybind11;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// "(3,)" or "(3, 3)".
std::string shape_text(const py::array& a);
/// x in Python's notation for a message: ascii(x) (a string keeps its own quotes, non-ASCII and
/// control characters escaped) on one line, cut after 60 characters.
std::string repr_of(const py::handle& x);
/// The shape an Eigen type is read from and written to: (rows,) for vectors, (rows, cols) else.
std::string shape_text(Eigen::Index rows, Eigen::Index cols, bool vector);

/// Any array-like as a C-contiguous double array; throws std::invalid_argument if it is not one.
Array as_array(const py::handle& obj, std::string_view where, std::string_view name);

/// A dynamic matrix from a 1-D (as one column) or 2-D array, as `ndim` says; throws
/// std::invalid_argument naming `where` and `name` for another number of dimensions.
Eigen::MatrixXd dynamic_matrix(const py::handle& obj, std::string_view where, std::string_view name, py::ssize_t ndim);

/// The result of a vectorised callback (`who`) as an array of `count` rows, each of shape
/// `row_shape` (() for numbers, (n,) for vectors); throws std::invalid_argument naming `who` for
/// any other shape.
Array batch_rows(const py::handle& result, std::size_t count, const std::vector<py::ssize_t>& row_shape,
                 std::string_view who);

/// The K rows of a vectorised callback's result as numbers or fixed-size Eigen vectors, read from
/// the array's memory (one shape check, no per-row conversion).
template <class R, std::size_t K>
std::array<R, K> batch_values(const py::handle& result, std::string_view who) {
  if constexpr (std::is_same_v<R, double>) {
    const Array a = batch_rows(result, K, {}, who);
    std::array<double, K> out;
    std::copy_n(a.data(), K, out.begin());
    return out;
  } else {
    static_assert(R::ColsAtCompileTime == 1 && R::RowsAtCompileTime > 0, "vectorised callbacks return numbers or vectors");
    constexpr Eigen::Index n = R::RowsAtCompileTime;
    const Array a = batch_rows(result, K, {n}, who);
    std::array<R, K> out;
    for (std::size_t k = 0; k < K; ++k) out[k] = Eigen::Map<const R>(a.data() + k * n);
    return out;
  }
}

/// A fixed-size Eigen vector (from a 1-D array of its length) or matrix (from a 2-D array of its
/// shape). Throws std::invalid_argument naming `where` and `name` on any other shape.
template <class T>
T to_eigen(const py::handle& obj, std::string_view where, std::string_view name) {
  constexpr Eigen::Index rows = T::RowsAtCompileTime, cols = T::ColsAtCompileTime;
  constexpr bool vector = cols == 1;
  static_assert(rows > 0 && cols > 0, "to_eigen converts to fixed-size Eigen types only");
  const Array a = as_array(obj, where, name);
  const bool fits = vector ? (a.ndim() == 1 && a.shape(0) == rows)
                           : (a.ndim() == 2 && a.shape(0) == rows && a.shape(1) == cols);
  if (!fits) {
    throw_invalid(where, name, "array of shape " + shape_text(a),
                  "must have shape " + shape_text(rows, cols, vector));
  }
  T out;
  const double* data = a.data();
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j) out(i, j) = data[i * cols + j];
  }
  return out;
}

/// The array of a sequence of fixed-size Eigen objects T, with one more leading axis: (count, rows)
/// or (count, rows, cols), or no rows at all (e.g. [] or a failed result's arrays). Throws
/// std::invalid_argument naming `where` and `name` on any other shape.
template <class T>
Array list_array(const py::handle& obj, std::string_view where, std::string_view name) {
  constexpr Eigen::Index rows = T::RowsAtCompileTime, cols = T::ColsAtCompileTime;
  constexpr bool vector = cols == 1;
  static_assert(rows > 0 && cols > 0, "sequences of fixed-size Eigen types only");
  const Array a = as_array(obj, where, name);
  if (a.ndim() >= 1 && a.shape(0) == 0) return a;
  const bool fits = vector ? (a.ndim() == 2 && a.shape(1) == rows)
                           : (a.ndim() == 3 && a.shape(1) == rows && a.shape(2) == cols);
  if (!fits) {
    const std::string count = a.ndim() >= 1 ? std::to_string(a.shape(0)) : "k";
    throw_invalid(where, name, "array of shape " + shape_text(a),
                  "must have shape (" + count + ", " + std::to_string(rows) +
                      (vector ? std::string(")") : ", " + std::to_string(cols) + ")"));
  }
  return a;
}

/// A sequence of fixed-size Eigen objects from list_array's array, read from its memory in one
/// pass (one shape check, no Python object per row: a trajectory of 2e6 nodes converts in
/// milliseconds, not seconds).
template <class T>
std::vector<T> to_eigen_list(const py::handle& obj, std::string_view where, std::string_view name) {
  const Array a = list_array<T>(obj, where, name);
  std::vector<T> out(static_cast<std::size_t>(a.shape(0)));
  const double* data = a.data();
  for (T& x : out) {
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      for (Eigen::Index j = 0; j < x.cols(); ++j) x(i, j) = *data++;
    }
  }
  return out;
}

/// The same sequence as the api's rows (api::Samples): one row of rows * cols numbers per object,
/// row-major within it; the array's memory copied in one pass.
template <class T>
api::Table to_rows(const py::handle& obj, std::string_view where, std::string_view name) {
  const Array a = list_array<T>(obj, where, name);
  const Eigen::Index count = a.shape(0);
  if (count == 0) return {};
  return Eigen::Map<const api::Table>(a.data(), count, T::RowsAtCompileTime * T::ColsAtCompileTime);
}

/// One Eigen object as a NumPy array ((rows,) for vectors, (rows, cols) otherwise).
template <class Derived>
py::array_t<double> to_numpy(const Eigen::DenseBase<Derived>& x) {
  const Eigen::Index rows = x.rows(), cols = x.cols();
  const bool vector = Derived::ColsAtCompileTime == 1;
  py::array_t<double> out(vector ? std::vector<py::ssize_t>{rows} : std::vector<py::ssize_t>{rows, cols});
  double* data = out.mutable_data();
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j) data[i * cols + j] = x(i, j);
  }
  return out;
}

/// A sequence of same-shaped Eigen objects stacked along a new first axis.
template <class T>
py::array_t<double> to_numpy(const std::vector<T>& xs) {
  constexpr Eigen::Index rows = T::RowsAtCompileTime, cols = T::ColsAtCompileTime;
  const auto count = static_cast<py::ssize_t>(xs.size());
  py::array_t<double> out(cols == 1 ? std::vector<py::ssize_t>{count, rows}
                                    : std::vector<py::ssize_t>{count, rows, cols});
  double* data = out.mutable_data();
  for (const T& x : xs) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      for (Eigen::Index j = 0; j < cols; ++j) *data++ = x(i, j);
    }
  }
  return out;
}

inline py::array_t<double> to_numpy(const std::vector<double>& xs) {
  return py::array_t<double>(static_cast<py::ssize_t>(xs.size()), xs.data());
}

/// The vector moved into a capsule that owns it as long as `array` (a view of it) lives.
template <class V>
py::capsule owning_capsule(V&& xs) {
  auto* owner = new std::decay_t<V>(std::move(xs));
  return py::capsule(owner, [](void* p) { delete static_cast<std::decay_t<V>*>(p); });
}

/// to_numpy without a copy, for the long per-node lists of a solution (2e6 nodes: 0.3 GB neither
/// copied nor allocated twice): the vector moves into the array's base object. Values, shape and
/// indexing are those of the copy; a matrix entry keeps Eigen's column-major layout (strides
/// (entry, 8, 8 rows)), so such an array is not C-contiguous, which NumPy handles everywhere.
template <class T>
py::array_t<double> to_numpy(std::vector<T>&& xs) {
  constexpr Eigen::Index rows = T::RowsAtCompileTime, cols = T::ColsAtCompileTime;
  if constexpr (sizeof(T) != sizeof(double) * rows * cols || T::IsRowMajor) {
    return to_numpy(static_cast<const std::vector<T>&>(xs));  // padded or row-major entries: copied
  } else {
    if (xs.empty()) return to_numpy(static_cast<const std::vector<T>&>(xs));
    const auto count = static_cast<py::ssize_t>(xs.size());
    constexpr auto entry = static_cast<py::ssize_t>(sizeof(T)), number = static_cast<py::ssize_t>(sizeof(double));
    double* data = xs.front().data();  // moving a vector keeps its storage
    py::capsule base = owning_capsule(std::move(xs));
    if constexpr (cols == 1) {
      return py::array_t<double>({count, py::ssize_t{rows}}, {entry, number}, data, base);
    } else {
      return py::array_t<double>({count, py::ssize_t{rows}, py::ssize_t{cols}}, {entry, number, number * rows}, data, base);
    }
  }
}

/// The api's rows (one T a row, row-major within it) as to_numpy of the sequence of T would give
/// them, without a copy: the table moves into the array's base object (C order).
template <class T>
py::array_t<double> rows_to_numpy(api::Table&& x) {
  constexpr Eigen::Index rows = T::RowsAtCompileTime, cols = T::ColsAtCompileTime;
  const auto count = static_cast<py::ssize_t>(x.rows());
  constexpr auto number = static_cast<py::ssize_t>(sizeof(double));
  if (count == 0) return to_numpy(std::vector<T>{});
  double* data = x.data();  // moving a matrix keeps its storage
  py::capsule base = owning_capsule(std::move(x));
  if constexpr (cols == 1) {
    return py::array_t<double>({count, py::ssize_t{rows}}, {number * rows, number}, data, base);
  } else {
    return py::array_t<double>({count, py::ssize_t{rows}, py::ssize_t{cols}}, {number * rows * cols, number * cols, number},
                               data, base);
  }
}

inline py::array_t<double> to_numpy(std::vector<double>&& xs) {
  if (xs.empty()) return to_numpy(static_cast<const std::vector<double>&>(xs));
  const auto count = static_cast<py::ssize_t>(xs.size());
  double* data = xs.data();
  py::capsule base = owning_capsule(std::move(xs));
  return py::array_t<double>({count}, {static_cast<py::ssize_t>(sizeof(double))}, data, base);
}

}  // namespace cartan::python
