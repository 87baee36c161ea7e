// The Python class GroupManifold (include/cartan/manifolds/group_manifold.hpp) in its own
// translation unit: one class over GroupManifold<G> for SO(3), H3, SE(2), SE(3) with any
// left-invariant connection, with the geometry methods of every manifold class
// (def_manifold_methods, general_binding.hpp); bind_general.cpp solves on it.

#include "general_binding.hpp"

namespace cartan::python {

namespace {

using namespace general_binding;

/// f(std::type_identity<G>{}) for the group named `group` (a name or a group class of this module).
template <class F>
decltype(auto) visit_group(const py::object& group, const std::string& where, F&& f) {
  std::string name;
  if (py::isinstance<py::str>(group)) {
    name = group.cast<std::string>();
  } else if (py::hasattr(group, "name") && py::hasattr(group, "element_shape")) {
    name = py::str(group.attr("name")).cast<std::string>();
  }
  if (name == "so3") return f(std::type_identity<groups::SO3>{});
  if (name == "heisenberg") return f(std::type_identity<groups::Heisenberg>{});
  if (name == "se2") return f(std::type_identity<groups::SE2>{});
  if (name == "se3") return f(std::type_identity<groups::SE3>{});
  throw_invalid(where, "group", repr_of(group),
                "is not one of: so3, heisenberg, se2, se3 (or cartan.SO3, cartan.Heisenberg, cartan.SE2, cartan.SE3)");
}

/// The group manifold for `connection`: a name with its parameter, or a `<Group>.Connection`.
template <groups::LieGroup G>
manifolds::GroupManifold<G> make_group_manifold(const py::object& connection, const py::object& lam,
                                                const py::object& metric, const py::object& alpha) {
  using GM = manifolds::GroupManifold<G>;
  constexpr int n = G::kDim;
  const std::string where = "GroupManifold";
  // Each connection takes exactly its own parameter (`needed`), or none.
  const auto takes = [&](const std::string& kind, std::string_view needed) {
    const std::pair<const char*, const py::object*> parameters[] = {{"lam", &lam}, {"metric", &metric}, {"alpha", &alpha}};
    for (const auto& [parameter, value] : parameters) {
      const bool is_needed = parameter == needed;
      if (is_needed && value->is_none()) throw_invalid(where, parameter, "None", "must be given for connection " + kind);
      if (!is_needed && !value->is_none()) {
        throw_invalid(where, parameter, repr_of(*value), "does not apply to connection " + kind);
      }
    }
  };
  if (py::isinstance<connections::InvariantConnection<G>>(connection)) {
    takes("<Group>.Connection", "");
    return GM(connection.cast<const connections::InvariantConnection<G>&>());
  }
  using connections::ConnectionKind;
  const std::string kind = py::isinstance<py::str>(connection) ? connection.cast<std::string>() : std::string();
  ConnectionKind parsed{};
  try {
    parsed = parse_enum<ConnectionKind>(kind, where);
  } catch (const std::invalid_argument&) {
    throw_invalid(where, "connection", repr_of(connection),
                  "is not one of: " + enum_choices<ConnectionKind>(", ") + " (or a left <Group>.Connection)");
  }
  switch (parsed) {
    case ConnectionKind::CartanSchouten: {
      takes(kind, "lam");
      const double l = number_arg<double>(lam, where, "lam");
      require_finite(l, where, "lam");
      return GM::cartan_schouten(l);
    }
    case ConnectionKind::LeviCivita:
      takes(kind, "metric");
      return GM::levi_civita(matrix_or_diagonal<n>(metric, where, "metric"));
    case ConnectionKind::Coefficients: {
      takes(kind, "alpha");
      std::vector<double> numbers;  // alpha[i][j][k] in (i, j, k) order, as GroupManifold::coefficients reads them
      for (const auto& plane : tensor_arg<n>(alpha, where, "alpha")) {  // plane(j, k) = alpha[i][j][k]
        for (int j = 0; j < n; ++j) {
          for (int k = 0; k < n; ++k) numbers.push_back(plane(j, k));
        }
      }
      return GM::coefficients(numbers);
    }
  }
  throw std::logic_error("make_group_manifold: unhandled ConnectionKind");
}

/// The bilinear map of `gm`'s connection as a (n, n, n) array: alpha(e_i, e_j) = sum_k alpha[i, j, k] e_k.
template <groups::LieGroup G>
py::array_t<double> alpha_array(const manifolds::GroupManifold<G>& gm) {
  constexpr int n = G::kDim;
  std::array<Square<n>, n> out;  // out[i](j, k) = alpha[i][j][k]
  for (int i = 0; i < n; ++i) out[i] = gm.connection().coefficients()[i].transpose();
  return tensor_numpy<n>(out);
}

/// A GroupManifold as the constructor's arguments (group name, connection word, its parameter:
/// lam, the metric at the identity, or alpha), for pickling: a result and a sweep's problem on
/// processes carry their space (as Sphere's and Euclidean's do).
py::tuple constructor_arguments(const AnyGroupManifold& h) {
  return visit_holder(h, [](const auto& gm) {
    using G = typename std::decay_t<decltype(gm)>::Group;
    const std::string name(gm.name());
    if (const auto l = gm.cartan_schouten_lambda()) return py::make_tuple(name, "cartan-schouten", *l);
    if (const auto g = gm.metric(G::identity())) return py::make_tuple(name, "levi-civita", to_numpy(*g));
    return py::make_tuple(name, "coefficients", alpha_array(gm));
  });
}

AnyGroupManifold from_constructor_arguments(const py::tuple& state) {
  constexpr const char* where = "GroupManifold";
  if (state.size() != 3) throw_invalid(where, "pickled state", std::to_string(state.size()) + " items", "must have 3");
  const py::object connection = state[1], parameter = state[2], none = py::none();
  const std::string kind = py::cast<std::string>(connection);
  return visit_group(state[0], where, [&]<class G>(std::type_identity<G>) {
    return AnyGroupManifold{make_group_manifold<G>(connection, kind == "cartan-schouten" ? parameter : none,
                                                   kind == "levi-civita" ? parameter : none,
                                                   kind == "coefficients" ? parameter : none)};
  });
}

}  // namespace

void bind_group_manifold(py::module_& m) {
  py::class_<AnyGroupManifold> cls(
      m, "GroupManifold",
      "A Lie group (so3, heisenberg, se2, se3) with a left-invariant connection, as a manifold: points are "
      "group elements, vectors left-trivialised algebra coordinates, the Christoffel map is the connection's "
      "bilinear map alpha.");
  cls.def(py::init([](const py::object& group, const py::object& connection, const py::object& lam,
                      const py::object& metric, const py::object& alpha) {
            return visit_group(group, "GroupManifold", [&]<class G>(std::type_identity<G>) {
              return AnyGroupManifold{make_group_manifold<G>(connection, lam, metric, alpha)};
            });
          }),
          py::arg("group"), py::arg("connection") = std::string(to_string(connections::ConnectionKind::CartanSchouten)),
          py::kw_only(), py::arg("lam") = py::none(),
          py::arg("metric") = py::none(), py::arg("alpha") = py::none(),
          "group: \"so3\", \"heisenberg\", \"se2\", \"se3\" or the group class. connection: \"cartan-schouten\" "
          "(with lam: alpha = lam ad), \"levi-civita\" (with metric, a symmetric positive-definite (n, n) matrix or "
          "its (n,) diagonal), \"coefficients\" (with alpha, a (n, n, n) array: alpha(e_i, e_j) = sum_k "
          "alpha[i, j, k] e_k), or a left <Group>.Connection object.");
  def_manifold_methods(cls, "GroupManifold");
  cls.def_property_readonly("group", [](const AnyGroupManifold& h) {
    return visit_holder(h, [](const auto& gm) -> py::object {
      return py::type::of<GroupTag<typename std::decay_t<decltype(gm)>::Group>>();
    });
  }, "The group class (cartan.SO3, ...).");
  cls.def_property_readonly("lam", [](const AnyGroupManifold& h) -> py::object {
    return visit_holder(h, [](const auto& gm) -> py::object {
      const auto l = gm.cartan_schouten_lambda();
      return l ? py::object(py::float_(*l)) : py::object(py::none());
    });
  }, "lam for a Cartan-Schouten connection, else None.");
  cls.def_property_readonly("alpha", [](const AnyGroupManifold& h) {
    return visit_holder(h, [](const auto& gm) { return alpha_array(gm); });
  }, "The bilinear map as a (n, n, n) array: alpha(e_i, e_j) = sum_k alpha[i, j, k] e_k.");
  cls.def(py::pickle(&constructor_arguments, &from_constructor_arguments));
  cls.def_property_readonly("connection", [](const AnyGroupManifold& h) {
    return visit_holder(h, [](const auto& gm) { return py::cast(gm.connection()); });
  }, "The connection as a <Group>.Connection object.");
  cls.def("__repr__", [](const AnyGroupManifold& h) {
    return visit_holder(h, [](const auto& gm) {
      using G = typename std::decay_t<decltype(gm)>::Group;
      const auto l = gm.cartan_schouten_lambda();
      const std::string text = "GroupManifold(\"" + std::string(gm.name()) + "\", ";
      if (l) return text + "\"cartan-schouten\", lam=" + format_value(*l) + ")";
      if (gm.metric(G::identity())) return text + "\"levi-civita\", metric=...)";
      return text + "\"coefficients\", alpha=...)";
    });
  });
}

}  // namespace cartan::python
