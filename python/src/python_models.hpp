#pragma once
// Reduced Lagrangians and Hamiltonians written in Python, adapted to the C++ concepts
// (lagrangian.hpp): any object with methods
//   Lagrangian:  value(t, g, v), momentum(t, g, v), group_gradient(t, g, v), velocity(t, g, mu)
//   Hamiltonian: value(t, g, mu), velocity(t, g, mu), group_gradient(t, g, mu)
// taking and returning NumPy arrays in the group's conventions (docs/conventions.md). The
// second derivatives that tangent-linear sweeps need come from the library's central
// differences of momentum and group_gradient (lagrangian_hessian_fd, lagrangian_hessian.hpp).
//
// Errors. The solvers treat an exception in a sweep as a failed evaluation and go on (a
// rejected Levenberg–Marquardt step). A Python error is a bug in user code, not a numerical
// outcome, so the first one is kept in the shared CallbackState, every later callback fails at
// once, and the binding re-raises the original exception after the solver returns
// (rethrow_callback_error). Callbacks run with the GIL held.

#include <exception>
#include <memory>
#include <optional>
#include <type_traits>
#include <string>
#include <utility>

#include "cartan/group.hpp"
#include "cartan/lagrangian.hpp"
#include "convert.hpp"

namespace cartan::python {

/// The first exception raised by a Python callback; shared by the copies of a model that the
/// solvers make (problems are copied by continuation).
struct CallbackState {
  std::exception_ptr first_error;
};

/// Re-raises the first callback error, if any (a Python exception keeps its type and traceback).
void rethrow_callback_error(const CallbackState& state);

/// The Python object and its methods, looked up once.
class PythonModel {
 public:
  PythonModel(const py::object& object, std::string_view kind, std::initializer_list<const char*> methods);
  const CallbackState& state() const { return *state_; }
  const py::object& object() const { return object_; }

 protected:
  /// Calls method `index` with (t, g, x) and converts the result to R, recording failures.
  template <class R, class E, class X>
  R call(std::size_t index, double t, const E& g, const X& x) const {
    if (state_->first_error) throw std::runtime_error(kind_ + ": an earlier callback failed");
    try {
      const py::object result = methods_[index](t, to_numpy(g), to_numpy(x));
      if constexpr (std::is_same_v<R, double>) {
        return result.cast<double>();
      } else {
        return to_eigen<R>(result, kind_ + "." + names_[index], "return value");
      }
    } catch (...) {
      state_->first_error = std::current_exception();
      throw;
    }
  }

 private:
  py::object object_;
  std::string kind_;
  std::vector<std::string> names_;
  std::vector<py::object> methods_;
  std::shared_ptr<CallbackState> state_ = std::make_shared<CallbackState>();
};

template <LieGroup G>
class PythonLagrangian : public PythonModel {
 public:
  explicit PythonLagrangian(const py::object& object)
      : PythonModel(object, "Lagrangian", {"value", "momentum", "group_gradient", "velocity"}) {}

  double value(double t, const ElementOf<G>& g, const TangentOf<G>& v) const { return call<double>(0, t, g, v); }
  CovectorOf<G> momentum(double t, const ElementOf<G>& g, const TangentOf<G>& v) const {
    return call<CovectorOf<G>>(1, t, g, v);
  }
  CovectorOf<G> group_gradient(double t, const ElementOf<G>& g, const TangentOf<G>& v) const {
    return call<CovectorOf<G>>(2, t, g, v);
  }
  TangentOf<G> velocity(double t, const ElementOf<G>& g, const CovectorOf<G>& mu) const {
    return call<TangentOf<G>>(3, t, g, mu);
  }
};

template <LieGroup G>
class PythonHamiltonian : public PythonModel {
 public:
  explicit PythonHamiltonian(const py::object& object)
      : PythonModel(object, "Hamiltonian", {"value", "velocity", "group_gradient"}) {}

  double value(double t, const ElementOf<G>& g, const CovectorOf<G>& mu) const { return call<double>(0, t, g, mu); }
  TangentOf<G> velocity(double t, const ElementOf<G>& g, const CovectorOf<G>& mu) const {
    return call<TangentOf<G>>(1, t, g, mu);
  }
  CovectorOf<G> group_gradient(double t, const ElementOf<G>& g, const CovectorOf<G>& mu) const {
    return call<CovectorOf<G>>(2, t, g, mu);
  }
};

template <class M>
inline constexpr bool kIsPythonModel = std::is_base_of_v<PythonModel, M>;

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
  std::optional<R> result;
  try {
    result.emplace(f(model));
  } catch (...) {
    rethrow_callback_error(model.state());
    throw;
  }
  rethrow_callback_error(model.state());
  return std::move(*result);
}

}  // namespace cartan::python
