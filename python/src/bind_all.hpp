#pragma once
// Everything cartan exposes for one group, from the templated binders: the group class with its
// operations, its Connection class, the classical integrators and the transported-velocity
// solvers for the listed built-in models and for Lagrangians written in Python.

#include "bind_connection.hpp"
#include "bind_models.hpp"
#include "bind_solvers.hpp"

namespace cartan::python {

template <groups::LieGroup G, class Lagrangians, class Hamiltonians, class SolverModels>
GroupClass<G> bind_all(py::module_& m, const char* name, const char* doc) {
  GroupClass<G> group = bind_group<G>(m, name, doc);
  bind_connection<G>(group, name);
  bind_mechanics<G>(group, name, Lagrangians{}, Hamiltonians{});
  bind_solvers<G>(group, name, SolverModels{});
  return group;
}

/// The inertia a built-in model was made from (a right-reduced model: its left-reduced one's).
template <class M>
const auto& inertia_of(const M& model) {
  if constexpr (requires { model.left_reduced(); }) {
    return model.left_reduced().inertia();
  } else {
    return model.inertia();
  }
}

/// py::init from an inertia, given as a (n, n) matrix or its (n,) diagonal (with kDefaultIdentity
/// the argument may be omitted: None, the identity); the read-only property `inertia` (n, n); and
/// pickling by the inertia (the model is rebuilt from the same, already symmetric, matrix, so
/// that a copy in another process computes bit for bit what the original does).
template <int N, bool kDefaultIdentity = false, class Make>
auto inertia_init(const char* name, Make make) {
  return [=](auto& cls) {
    using Matrix = Eigen::Matrix<double, N, N>;
    auto init = py::init([=](const py::object& inertia) {
      return make(inertia.is_none() ? Matrix::Identity().eval() : inertia_matrix<N>(inertia, name));
    });
    const char* doc = "From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal.";
    if constexpr (kDefaultIdentity) {
      cls.def(std::move(init), py::arg("inertia") = py::none(), doc);
    } else {
      cls.def(std::move(init), py::arg("inertia"), doc);
    }
    using M = typename std::decay_t<decltype(cls)>::type;
    cls.def_property_readonly("inertia", [](const M& model) { return to_numpy(Matrix(inertia_of(model))); },
                              "The inertia, a symmetric (n, n) matrix.");
    cls.def(py::pickle([](const M& model) { return py::make_tuple(to_numpy(Matrix(inertia_of(model)))); },
                       [=](const py::tuple& state) {
                         if (state.size() != 1) throw_invalid(name, "pickled state", std::to_string(state.size()) + " items",
                                                              "must be 1 item, the inertia");
                         return make(inertia_matrix<N>(state[0], name));
                       }));
  };
}

}  // namespace cartan::python
