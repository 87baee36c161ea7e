#pragma once
// Reduced Lagrangians and Hamiltonians written in Python, adapted to the C++ concepts
// (lagrangian.hpp): any object with methods
//   Lagrangian:  value(t, g, v), momentum(t, g, v), group_gradient(t, g, v), velocity(t, g, mu)
//   Hamiltonian: value(t, g, mu), velocity(t, g, mu), group_gradient(t, g, mu)
// taking and returning NumPy arrays in the group's conventions (docs/conventions.md). The
// second derivatives that tangent-linear sweeps need come from an optional method
// hessian(t, g, v) or else from the library's central differences of momentum and
// group_gradient (lagrangian_hessian_fd, lagrangian_hessian.hpp).
//
// Vectorised models. An object whose attribute `vectorized` is true takes and returns stacked
// points: t (K,), g (K, *element shape), v or mu (K, n), and returns (K,) values or (K, n) rows.
// Single evaluations are batches of one; the finite-difference Hessian's 4 n points go in one
// call of momentum and one of group_gradient (2 callbacks a node instead of 8 n). The optional
// `hessian` is always called with one point.
//
// Errors. The solvers treat an exception in a sweep as a failed evaluation and go on (a
// rejected Levenberg–Marquardt step). A Python error is a bug in user code, not a numerical
// outcome, so the first one is kept in the shared CallbackState, every later callback fails at
// once, and the binding re-raises the original exception after the solver returns
// (guarded_callback, run_with_callbacks; cartan.solve_bvp's callbacks use the same two).
// Callbacks run with the GIL held.

#include <algorithm>
#include <array>
#include <exception>
#include <memory>
#include <cmath>
#include <optional>
#include <type_traits>
#include <string>
#include <utility>

#include "cartan/groups/group.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"
#include "cartan/monitor.hpp"
#include "convert.hpp"

namespace cartan::python {

/// The first exception raised by a Python callback; shared by the copies of a model that the
/// solvers make (problems are copied by continuation).
struct CallbackState {
  std::exception_ptr first_error;
};

/// Re-raises the first callback error, if any (a Python exception keeps its type and traceback).
void rethrow_callback_error(const CallbackState& state);

/// Runs one callback f() on behalf of `who` ("Lagrangian.momentum"), recording its first
/// exception in `state`; once one is recorded, every later callback fails at once.
template <class F>
auto guarded_callback(CallbackState& state, const std::string& who, F&& f) {
  if (state.first_error) throw std::runtime_error(who + ": an earlier callback failed");
  try {
    return f();
  } catch (...) {
    state.first_error = std::current_exception();
    throw;
  }
}

/// Runs a solver f() whose callbacks are guarded by `state` and returns its result; the first
/// callback error, if any, is re-raised in place of whatever the solver made of it.
template <class F>
auto run_with_callbacks(const CallbackState& state, F&& f) {
  using R = decltype(f());
  std::optional<R> result;
  try {
    result.emplace(f());
  } catch (...) {
    rethrow_callback_error(state);
    throw;
  }
  rethrow_callback_error(state);
  return std::move(*result);
}

/// The monitor of a Python solve (cartan.solve, cartan.solve_general): Ctrl-C and exceptions of
/// `progress` stop it by raising the Python error through the solver (error_already_set).
SolveMonitor python_monitor(const py::object& progress);

/// Converts a callback's return value; `where` names the method ("Lagrangian.momentum").
template <class R>
struct FromPython {
  static R convert(const py::object& value, const std::string& where) {
    return to_eigen<R>(value, where, "return value");
  }
};

template <>
struct FromPython<double> {
  static double convert(const py::object& value, const std::string&) { return value.cast<double>(); }
};

/// The optional `hessian(t, g, v)` callback returns a dict of (n, n) arrays with the keys of
/// LagrangianHessian (what cartan.lagrangian_hessian returns).
template <groups::LieGroup G>
struct FromPython<mechanics::LagrangianHessian<G>> {
  static mechanics::LagrangianHessian<G> convert(const py::object& value, const std::string& where) {
    const auto matrix = [&](const char* key) {
      return to_eigen<groups::AlgebraMatrixOf<G>>(value[py::str(key)], where, std::string("return value[\"") + key + "\"]");
    };
    return {matrix("momentum_v"), matrix("momentum_g"), matrix("gradient_v"), matrix("gradient_g")};
  }
};

/// The Python object and its methods, looked up once (optional ones may be missing).
class PythonModel {
 public:
  PythonModel(const py::object& object, std::string_view kind, std::initializer_list<const char*> required,
              std::initializer_list<const char*> optional = {});
  const CallbackState& state() const { return *state_; }
  const py::object& object() const { return object_; }

 protected:
  bool has(std::size_t index) const { return !methods_[index].is_none(); }

  /// Calls method `index` with (t, g, x) and converts the result to R, recording failures. A
  /// vectorised model gets a batch of one point (call_batch).
  template <class R, class E, class X>
  R call(std::size_t index, double t, const E& g, const X& x) const {
    if (vectorized_) return call_batch<R>(index, t, std::array<E, 1>{g}, std::array<X, 1>{x})[0];
    return call_one<R>(index, t, g, x);
  }

  /// Calls method `index` with (t, g, x) as they are (never batched: the optional `hessian`).
  template <class R, class E, class X>
  R call_one(std::size_t index, double t, const E& g, const X& x) const {
    const std::string who = kind_ + "." + names_[index];
    return guarded_callback(*state_, who, [&] {
      // A non-finite value from finite arguments is named at once (require_finite_result).
      R result = FromPython<R>::convert(methods_[index](t, to_numpy(g), to_numpy(x)), who);
      return require_finite_ ? mechanics::require_finite_result(result, who, t, g, x) : result;
    });
  }

  /// A vectorised model (attribute `vectorized` true): one call of method `index` with the K
  /// points stacked along a new first axis (t (K,), g (K, *element shape), x (K, n)); row k of
  /// its result is the value at point k.
  template <class R, class E, class X, std::size_t K>
  std::array<R, K> call_batch(std::size_t index, double t, const std::array<E, K>& g, const std::array<X, K>& x) const {
    const std::string who = kind_ + "." + names_[index];
    return guarded_callback(*state_, who, [&] {
      py::array_t<double> times(static_cast<py::ssize_t>(K));
      std::fill_n(times.mutable_data(), K, t);
      const std::array<R, K> out = batch_values<R, K>(
          methods_[index](times, to_numpy(std::vector<E>(g.begin(), g.end())), to_numpy(std::vector<X>(x.begin(), x.end()))),
          who);
      for (std::size_t k = 0; require_finite_ && k < K; ++k) mechanics::require_finite_result(out[k], who, t, g[k], x[k]);
      return out;
    });
  }

  bool vectorized() const { return vectorized_; }

  /// false: a non-finite result is returned as it is (check_lagrangian reports it).
  bool require_finite_ = true;

 private:
  py::object object_;
  std::string kind_;
  std::vector<std::string> names_;
  std::vector<py::object> methods_;
  bool vectorized_ = false;
  std::shared_ptr<CallbackState> state_ = std::make_shared<CallbackState>();
};

template <groups::LieGroup G>
class PythonLagrangian : public PythonModel {
 public:
  explicit PythonLagrangian(const py::object& object)
      : PythonModel(object, "Lagrangian", {"value", "momentum", "group_gradient", "velocity"}, {"hessian"}) {}

  double value(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const { return call<double>(0, t, g, v); }
  groups::CovectorOf<G> momentum(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return call<groups::CovectorOf<G>>(1, t, g, v);
  }
  groups::CovectorOf<G> group_gradient(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return call<groups::CovectorOf<G>>(2, t, g, v);
  }
  groups::TangentOf<G> velocity(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return call<groups::TangentOf<G>>(3, t, g, mu);
  }
  /// Second derivatives for the tangent-linear sweeps: the object's `hessian` if it has one,
  /// else central differences of momentum and group_gradient (lagrangian_hessian_fd), the 4 dim
  /// points of the stencil in one call of each for a vectorised model (2 callbacks, not 8 dim).
  mechanics::LagrangianHessian<G> hessian(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    if (has(4)) return call_one<mechanics::LagrangianHessian<G>>(4, t, g, v);
    if (!vectorized()) return mechanics::lagrangian_hessian_fd<G>(*this, t, g, v);
    const mechanics::HessianStencil<G> s = mechanics::hessian_stencil<G>(g, v);
    return mechanics::hessian_from_stencil<G>(s, call_batch<groups::CovectorOf<G>>(1, t, s.g, s.v),
                                              call_batch<groups::CovectorOf<G>>(2, t, s.g, s.v));
  }
  /// Whether the object has its own hessian (what check_lagrangian checks).
  bool has_hessian() const { return has(4); }
};

/// A Python Lagrangian as check_lagrangian sees it: non-finite results are returned (and
/// reported by the check), not raised; a Python exception is still re-raised.
template <groups::LieGroup G>
class CheckedPythonLagrangian : public PythonLagrangian<G> {
 public:
  explicit CheckedPythonLagrangian(const py::object& object) : PythonLagrangian<G>(object) {
    this->require_finite_ = false;
  }
};

template <groups::LieGroup G>
class PythonHamiltonian : public PythonModel {
 public:
  explicit PythonHamiltonian(const py::object& object)
      : PythonModel(object, "Hamiltonian", {"value", "velocity", "group_gradient"}) {}

  double value(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const { return call<double>(0, t, g, mu); }
  groups::TangentOf<G> velocity(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return call<groups::TangentOf<G>>(1, t, g, mu);
  }
  groups::CovectorOf<G> group_gradient(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return call<groups::CovectorOf<G>>(2, t, g, mu);
  }
};

/// Runs f(model) for the built-in model type that `object` is an instance of (a C++ class bound
/// to Python), or for the Python adapter Fallback(object) when it is none of them. Built-in
/// models run without the GIL; Python ones hold it, and their first callback error is re-raised.
template <class Fallback, class... Builtin, class F>
auto visit_model(const py::handle& object, F&& f) {
  using R = decltype(f(std::declval<const Fallback&>()));
  std::optional<R> out;
  const auto try_one = [&]<class M>(std::type_identity<M>) {
    if (out || !py::isinstance<M>(object)) return;
    const M& model = object.cast<const M&>();
    py::gil_scoped_release release;
    out.emplace(f(model));
  };
  (try_one(std::type_identity<Builtin>{}), ...);
  (void)try_one;  // no built-in models for this group
  if (out) return std::move(*out);
  const Fallback model(py::reinterpret_borrow<py::object>(object));
  return run_with_callbacks(model.state(), [&] { return f(model); });
}

}  // namespace cartan::python
