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

/// py::init from an inertia, given as a (n, n) matrix or its (n,) diagonal; with
/// kDefaultIdentity the argument may be omitted (None: the identity).
template <int N, bool kDefaultIdentity = false, class Make>
auto inertia_init(const char* name, Make make) {
  return [=](auto& cls) {
    auto init = py::init([=](const py::object& inertia) {
      return make(inertia.is_none() ? Eigen::Matrix<double, N, N>::Identity().eval()
                                    : inertia_matrix<N>(inertia, name));
    });
    const char* doc = "From a symmetric positive-definite inertia: a (n, n) matrix or its (n,) diagonal.";
    if constexpr (kDefaultIdentity) {
      cls.def(std::move(init), py::arg("inertia") = py::none(), doc);
    } else {
      cls.def(std::move(init), py::arg("inertia"), doc);
    }
  };
}

}  // namespace cartan::python
