#pragma once
// The one templated binder of a Lie group (STYLE practice 9): a Python class with static
// methods over the group's math (group.hpp), the same for every group. Elements are NumPy
// arrays in the group's own coordinates: (3, 3) for SO(3) and SE(2), (4, 4) for SE(3), (3,)
// (a, b, c) for the Heisenberg group; algebra vectors and covectors are 1-D of length dim.

#include <string>
#include <vector>

#include "cartan/groups/group.hpp"
#include "cartan/models/catalogue.hpp"
#include "convert.hpp"

namespace cartan::python {

/// The C++ type behind the Python class of group G (it has no instances: all methods are static).
template <groups::LieGroup G>
struct GroupTag {};

template <groups::LieGroup G>
using GroupClass = py::class_<GroupTag<G>>;

/// A problem's endpoint x as every door reads one (models::check_element, the CLI's and a result
/// file's rule): an element within kElementTolerance, projected onto the group, so that input
/// rounded to a few digits (a CLI file's gT, off by 4e-8) is the exact element the CLI solves.
template <groups::LieGroup G>
groups::ElementOf<G> checked_endpoint(const groups::ElementOf<G>& x, const std::string& where, const std::string& name) {
  const std::vector<double> numbers = models::element_numbers(x);
  models::find_model(G::name(), {}, where).check_element(numbers, where, name);
  return models::element_of<G>(numbers);
}

/// Converts the argument `name` of `Group.method` to G's element, tangent or algebra-matrix type.
template <groups::LieGroup G>
struct Args {
  std::string group;
  groups::ElementOf<G> element(const py::handle& x, std::string_view method, std::string_view name) const {
    return to_eigen<groups::ElementOf<G>>(x, group + "." + std::string(method), name);
  }
  /// A problem's endpoint (checked_endpoint).
  groups::ElementOf<G> endpoint(const py::handle& x, std::string_view method, std::string_view name) const {
    return checked_endpoint<G>(element(x, method, name), group + "." + std::string(method), std::string(name));
  }
  groups::TangentOf<G> tangent(const py::handle& x, std::string_view method, std::string_view name) const {
    return to_eigen<groups::TangentOf<G>>(x, group + "." + std::string(method), name);
  }
  typename G::MatrixRep matrix_rep(const py::handle& x, std::string_view method, std::string_view name) const {
    return to_eigen<typename G::MatrixRep>(x, group + "." + std::string(method), name);
  }
};

template <groups::LieGroup G>
GroupClass<G> bind_group(py::module_& m, const char* name, const char* doc) {
  GroupClass<G> cls(m, name, doc);
  const Args<G> a{name};
  cls.attr("name") = std::string(G::name());
  cls.attr("dim") = G::kDim;
  constexpr int rows = groups::ElementOf<G>::RowsAtCompileTime, cols = groups::ElementOf<G>::ColsAtCompileTime;
  cls.attr("element_shape") = cols == 1 ? py::make_tuple(rows) : py::make_tuple(rows, cols);
  cls.def_static("identity", [] { return to_numpy(G::identity()); }, "The identity element.");
  cls.def_static("compose", [a](const py::object& g, const py::object& h) {
    return to_numpy(G::compose(a.element(g, "compose", "g"), a.element(h, "compose", "h")));
  }, py::arg("g"), py::arg("h"), "The product g h.");
  cls.def_static("inverse", [a](const py::object& g) { return to_numpy(G::inverse(a.element(g, "inverse", "g"))); },
                 py::arg("g"), "The inverse g^-1.");
  cls.def_static("exp", [a](const py::object& v) { return to_numpy(G::exp(a.tangent(v, "exp", "v"))); },
                 py::arg("v"), "The group exponential of v in the algebra (coordinates).");
  cls.def_static("log", [a](const py::object& g) { return to_numpy(G::log(a.element(g, "log", "g"))); },
                 py::arg("g"), "The principal logarithm, in algebra coordinates.");
  cls.def_static("hat", [a](const py::object& v) { return to_numpy(G::hat(a.tangent(v, "hat", "v"))); },
                 py::arg("v"), "The matrix sum_i v_i E_i of algebra coordinates v.");
  cls.def_static("vee", [a](const py::object& x) { return to_numpy(G::vee(a.matrix_rep(x, "vee", "X"))); },
                 py::arg("X"), "The coordinates of an algebra matrix (inverse of hat).");
  cls.def_static("matrix", [a](const py::object& g) { return to_numpy(G::matrix(a.element(g, "matrix", "g"))); },
                 py::arg("g"), "A faithful matrix representation of g.");
  cls.def_static("Ad", [a](const py::object& g) { return to_numpy(G::Ad(a.element(g, "Ad", "g"))); },
                 py::arg("g"), "The matrix of Ad_g on algebra coordinates.");
  cls.def_static("ad", [a](const py::object& v) { return to_numpy(G::ad(a.tangent(v, "ad", "v"))); },
                 py::arg("v"), "The matrix of ad_v = [v, .] on algebra coordinates.");
  cls.def_static("ad_star", [a](const py::object& v, const py::object& mu) -> py::object {
    const groups::TangentOf<G> vv = a.tangent(v, "ad_star", "v");
    if (mu.is_none()) return to_numpy(groups::coad<G>(vv));
    return to_numpy(groups::coad<G>(vv, a.tangent(mu, "ad_star", "mu")));
  }, py::arg("v"), py::arg("mu") = py::none(),
     "ad*_v mu = ad_v^T mu (docs/conventions.md); the matrix ad_v^T when mu is omitted.");
  cls.def_static("bracket", [a](const py::object& u, const py::object& v) {
    return to_numpy(groups::bracket<G>(a.tangent(u, "bracket", "u"), a.tangent(v, "bracket", "v")));
  }, py::arg("u"), py::arg("v"), "The Lie bracket [u, v] = ad_u v.");
  cls.def_static("left_translate", [a](const py::object& g, const py::object& v) {
    return to_numpy(G::left_translate(a.element(g, "left_translate", "g"), a.tangent(v, "left_translate", "v")));
  }, py::arg("g"), py::arg("v"), "d(L_g)_e v, a tangent vector at g in ambient coordinates.");
  cls.def_static("left_trivialise", [a](const py::object& g, const py::object& x) {
    return to_numpy(G::left_trivialise(a.element(g, "left_trivialise", "g"), a.element(x, "left_trivialise", "X")));
  }, py::arg("g"), py::arg("X"), "g^-1 X for a tangent vector X at g (ambient coordinates).");
  cls.def_static("validate", [a](const py::object& g) { G::validate(a.element(g, "validate", "g"), "g"); },
                 py::arg("g"), "Raises ValueError unless g is a valid element (to the group's tolerance).");
  return cls;
}

}  // namespace cartan::python
