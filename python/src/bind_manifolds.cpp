// The manifolds with a linear connection (include/cartan/manifolds) as Python classes, in their
// own translation unit; bind_general.cpp solves on them (general_binding.hpp holds both halves'
// types and argument helpers).
//
// Python classes: Sphere, HyperbolicPlane (Quadric<+-1>), Euclidean (R^2 or R^3 with constant
// Christoffel symbols: one class over Euclidean<2> and Euclidean<3>), Chart (R^2 or R^3 with
// Christoffel symbols from Python callables) and GroupManifold (one class over GroupManifold<G>
// for SO(3), H3, SE(2), SE(3) with any left-invariant connection). Each has the same geometry
// methods (christoffel, torsion, curvature, step, difference, transport_along_step,
// tangent_basis, ...), bound once by def_manifold_methods.

#include "general_binding.hpp"

namespace cartan::python {

namespace {

using namespace general_binding;
using manifolds::HyperbolicPlane;
using manifolds::Sphere;

template <class Holder>
void def_manifold_methods(py::class_<Holder>& cls, const std::string& name) {
  cls.def_property_readonly("name", [](const Holder& h) {
    return visit_holder(h, [](const auto& m) { return std::string(m.name()); });
  }, "The manifold's name (\"sphere\", \"hyperbolic-plane\", \"euclidean\", or the group's).");
  cls.def_property_readonly("dim", [](const Holder& h) {
    return visit_holder(h, [](const auto& m) { return std::decay_t<decltype(m)>::kDim; });
  }, "m, the dimension (the length of v and mu).");
  cls.def_property_readonly("ambient_dim", [](const Holder& h) {
    return visit_holder(h, [](const auto& m) { return std::decay_t<decltype(m)>::kAmbientDim; });
  }, "d >= m, the length of the vectors that represent tangent vectors.");
  cls.def_property_readonly("point_shape", [](const Holder& h) {
    return visit_holder(h, [](const auto& m) {
      using P = PointOf<std::decay_t<decltype(m)>>;
      constexpr int rows = P::RowsAtCompileTime, cols = P::ColsAtCompileTime;
      return cols == 1 ? py::make_tuple(rows) : py::make_tuple(rows, cols);
    });
  }, "The shape of a point: (3,) on the quadrics, (m,) in R^m, the group element's shape.");

  cls.def("christoffel", [name](const Holder& h, const py::object& q, const py::object& x, const py::object& y) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      const std::string w = name + ".christoffel";
      return to_numpy(m.christoffel(point_arg(m, q, w, "q"), finite_arg<VectorOf<M>>(x, w, "x"),
                                    finite_arg<VectorOf<M>>(y, w, "y")));
    });
  }, py::arg("q"), py::arg("x"), py::arg("y"),
     "Gamma_q(x, y): nabla_{q'} Y = y' + Gamma_q(u, y) for a curve with represented velocity u.");
  cls.def("frame_bracket", [name](const Holder& h, const py::object& x, const py::object& y) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      const std::string w = name + ".frame_bracket";
      return to_numpy(m.frame_bracket(finite_arg<VectorOf<M>>(x, w, "x"), finite_arg<VectorOf<M>>(y, w, "y")));
    });
  }, py::arg("x"), py::arg("y"), "The bracket of the constant fields x, y (0, or [x, y] on a group).");
  cls.def("torsion", [name](const Holder& h, const py::object& q, const py::object& x, const py::object& y) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      const std::string w = name + ".torsion";
      return to_numpy(manifolds::torsion(m, point_arg(m, q, w, "q"), finite_arg<VectorOf<M>>(x, w, "x"),
                                         finite_arg<VectorOf<M>>(y, w, "y")));
    });
  }, py::arg("q"), py::arg("x"), py::arg("y"), "T(x, y) = nabla_x y - nabla_y x - [x, y] at q.");
  cls.def("curvature", [name](const Holder& h, const py::object& q, const py::object& x, const py::object& y,
                              const py::object& z) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      const std::string w = name + ".curvature";
      return to_numpy(manifolds::curvature(m, point_arg(m, q, w, "q"), finite_arg<VectorOf<M>>(x, w, "x"),
                                           finite_arg<VectorOf<M>>(y, w, "y"), finite_arg<VectorOf<M>>(z, w, "z")));
    });
  }, py::arg("q"), py::arg("x"), py::arg("y"), py::arg("z"),
     "R(x, y) z = nabla_x nabla_y z - nabla_y nabla_x z - nabla_[x,y] z at q.");
  cls.def("step", [name](const Holder& h, const py::object& q, const py::object& x) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      const std::string w = name + ".step";
      return to_numpy(m.step(point_arg(m, q, w, "q"), finite_arg<VectorOf<M>>(x, w, "x")));
    });
  }, py::arg("q"), py::arg("x"),
     "The end of the manifold's piece s -> step(q, s x) at s = 1 (q + x, a geodesic, g exp(x)).");
  cls.def("difference", [name](const Holder& h, const py::object& a, const py::object& b) {
    return visit_holder(h, [&](const auto& m) {
      const std::string w = name + ".difference";
      return to_numpy(m.difference(point_arg(m, a, w, "a"), point_arg(m, b, w, "b")));
    });
  }, py::arg("a"), py::arg("b"), "The x with step(a, x) = b (the local inverse of step).");
  cls.def("transport_along_step", [name](const Holder& h, const py::object& q, const py::object& x) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      const std::string w = name + ".transport_along_step";
      return to_numpy(m.transport_along_step(point_arg(m, q, w, "q"), finite_arg<VectorOf<M>>(x, w, "x")));
    });
  }, py::arg("q"), py::arg("x"), "The (d, d) matrix of parallel transport along s -> step(q, s x), s in [0, 1].");
  cls.def("tangent_basis", [name](const Holder& h, const py::object& q) {
    return visit_holder(h, [&](const auto& m) { return to_numpy(m.tangent_basis(point_arg(m, q, name + ".tangent_basis", "q"))); });
  }, py::arg("q"), "A (d, m) basis of T_qQ (orthonormal where there is a metric): the default frame0.");
  cls.def("metric", [name](const Holder& h, const py::object& q) {
    return visit_holder(h, [&](const auto& m) -> py::object {
      const auto g = manifolds::metric_at(m, point_arg(m, q, name + ".metric", "q"));
      return g ? py::object(to_numpy(*g)) : py::object(py::none());
    });
  }, py::arg("q"), "The (d, d) matrix of the metric the connection preserves, or None.");
  cls.def("torsion_components", [name](const Holder& h, const py::object& q, const py::object& frame) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      constexpr int n = M::kDim;
      const std::string w = name + ".torsion_components";
      const PointOf<M> p = point_arg(m, q, w, "q");
      const FrameOf<M> e = frame.is_none() ? m.tangent_basis(p) : finite_arg<FrameOf<M>>(frame, w, "frame");
      const auto c = manifolds::torsion_components(m, p, e);  // c[i](k, j) = T_ij^k
      std::array<Square<n>, n> out;                             // out[i](j, k) = T_ij^k
      for (int i = 0; i < n; ++i) out[i] = c[i].transpose();
      return tensor_numpy<n>(out);
    });
  }, py::arg("q"), py::arg("frame") = py::none(),
     "T[i, j, k] = T_ij^k with T(e_i, e_j) = T_ij^k e_k in the frame (default tangent_basis(q)).");
  cls.def("curvature_components", [name](const Holder& h, const py::object& q, const py::object& frame) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      constexpr int n = M::kDim;
      const std::string w = name + ".curvature_components";
      const PointOf<M> p = point_arg(m, q, w, "q");
      const FrameOf<M> e = frame.is_none() ? m.tangent_basis(p) : finite_arg<FrameOf<M>>(frame, w, "frame");
      const auto c = manifolds::curvature_components(m, p, e);  // c[i][j](l, k) = R_ijk^l
      py::array_t<double> out({n, n, n, n});
      double* data = out.mutable_data();
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          for (int k = 0; k < n; ++k) {
            for (int l = 0; l < n; ++l) *data++ = c[i][j](l, k);
          }
        }
      }
      return out;
    });
  }, py::arg("q"), py::arg("frame") = py::none(),
     "R[i, j, k, l] = R_ijk^l with R(e_i, e_j) e_k = R_ijk^l e_l in the frame (default tangent_basis(q)).");
  cls.def("has_parallel_torsion_and_curvature", [](const Holder& h) {
    return visit_holder(h, [](const auto& m) { return m.has_parallel_torsion_and_curvature(); });
  }, "True when nabla T = nabla R = 0 (the solver then computes the frame components once).");
  cls.def("validate", [](const Holder& h, const py::object& q) {
    visit_holder(h, [&](const auto& m) { (void)point_arg(m, q, "validate", "q"); });
  }, py::arg("q"), "Raises ValueError unless q is a valid point of the manifold.");
}

template <class Q>
py::class_<Q> bind_quadric(py::module_& m, const char* name, const char* doc) {
  py::class_<Q> cls(m, name, doc);
  cls.def(py::init<>());
  def_manifold_methods(cls, name);
  cls.def("__repr__", [name](const Q&) { return std::string(name) + "()"; });
  return cls;
}

// ---- GroupManifold ----------------------------------------------------------------------------

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
  const std::string kind = py::isinstance<py::str>(connection) ? connection.cast<std::string>() : std::string();
  if (kind == "cartan-schouten") {
    takes(kind, "lam");
    const double l = number_arg<double>(lam, where, "lam");
    require_finite(l, where, "lam");
    return GM::cartan_schouten(l);
  }
  if (kind == "levi-civita") {
    takes(kind, "metric");
    return GM::levi_civita(matrix_or_diagonal<n>(metric, where, "metric"));
  }
  if (kind == "coefficients") {
    takes(kind, "alpha");
    const auto a = tensor_arg<n>(alpha, where, "alpha");  // a[i](j, k) = alpha[i][j][k]
    typename connections::InvariantConnection<G>::Coefficients c;  // c[i](k, j): column j is alpha(e_i, e_j)
    for (int i = 0; i < n; ++i) c[i] = a[i].transpose();
    return GM(connections::InvariantConnection<G>(groups::Side::Left, c));
  }
  throw_invalid(where, "connection", repr_of(connection),
                "is not one of: cartan-schouten, levi-civita, coefficients (or a left <Group>.Connection)");
}

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
          py::arg("group"), py::arg("connection") = "cartan-schouten", py::kw_only(), py::arg("lam") = py::none(),
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
    return visit_holder(h, [](const auto& gm) {
      using G = typename std::decay_t<decltype(gm)>::Group;
      constexpr int n = G::kDim;
      std::array<Square<n>, n> out;  // out[i](j, k) = alpha[i][j][k]
      for (int i = 0; i < n; ++i) out[i] = gm.connection().coefficients()[i].transpose();
      return tensor_numpy<n>(out);
    });
  }, "The bilinear map as a (n, n, n) array: alpha(e_i, e_j) = sum_k alpha[i, j, k] e_k.");
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

// ---- Euclidean --------------------------------------------------------------------------------

template <int N>
EuclideanManifold make_euclidean(const py::object& christoffel) {
  using E = manifolds::Euclidean<N>;
  if (christoffel.is_none()) return {E()};
  const auto t = tensor_arg<N>(christoffel, "Euclidean", "christoffel");  // t[k](i, j) = Gamma^k_ij
  typename E::Coefficients c;                                              // c[i](k, j) = Gamma^k_ij
  for (int i = 0; i < N; ++i) {
    for (int k = 0; k < N; ++k) c[i].row(k) = t[k].row(i);
  }
  return {E(c)};
}

void bind_euclidean(py::module_& m) {
  py::class_<EuclideanManifold> cls(
      m, "Euclidean", "R^2 or R^3 with a constant linear connection nabla_{e_i} e_j = Gamma^k_ij e_k (any torsion "
                      "and curvature); points and vectors are coordinates.");
  cls.def(py::init([](const py::object& christoffel, const py::object& dim) {
            int n = 0;
            if (!christoffel.is_none()) {
              const Array a = as_array(christoffel, "Euclidean", "christoffel");
              n = a.ndim() >= 1 ? static_cast<int>(a.shape(0)) : 0;
              if (n != 2 && n != 3) {
                throw_invalid("Euclidean", "christoffel", "array of shape " + shape_text(a),
                              "must have shape (2, 2, 2) or (3, 3, 3)");
              }
            }
            if (!dim.is_none()) {
              const int d = number_arg<int>(dim, "Euclidean", "dim");
              if ((d != 2 && d != 3) || (n != 0 && d != n)) {
                throw_invalid("Euclidean", "dim", std::to_string(d),
                              n != 0 ? "does not match christoffel (of dimension " + std::to_string(n) + ")"
                                     : "must be 2 or 3");
              }
              n = d;
            }
            if (n == 0) throw_invalid("Euclidean", "dim", "None", "must be given (2 or 3) when christoffel is None");
            return n == 2 ? make_euclidean<2>(christoffel) : make_euclidean<3>(christoffel);
          }),
          py::arg("christoffel") = py::none(), py::kw_only(), py::arg("dim") = py::none(),
          "christoffel: a (m, m, m) array with christoffel[k, i, j] = Gamma^k_ij (m = 2 or 3), or None with "
          "dim = m for the flat, torsion-free connection.");
  def_manifold_methods(cls, "Euclidean");
  cls.def_property_readonly("christoffel_symbols", [](const EuclideanManifold& h) {
    return visit_holder(h, [](const auto& e) {
      constexpr int n = std::decay_t<decltype(e)>::kDim;
      std::array<Square<n>, n> out;  // out[k](i, j) = Gamma^k_ij
      for (int i = 0; i < n; ++i) {
        for (int k = 0; k < n; ++k) out[k].row(i) = e.coefficients()[i].row(k);
      }
      return tensor_numpy<n>(out);
    });
  }, "The (m, m, m) array christoffel[k, i, j] = Gamma^k_ij.");
  cls.def("__repr__", [](const EuclideanManifold& h) {
    return visit_holder(h, [](const auto& e) { return "Euclidean(dim=" + std::to_string(e.kDim) + ")"; });
  });
}

// ---- Chart ------------------------------------------------------------------------------------

/// A Python callable of the point as a field of the chart: the result converted by `convert`;
/// a Python exception is recorded for the solve that runs (callbacks.state), and during a solve
/// a later call fails at once.
template <int N, class R, class Convert>
auto chart_field(const std::shared_ptr<ChartCallbacks>& callbacks, py::object fn, const char* who, Convert convert) {
  return [callbacks, fn = std::move(fn), who, convert](const Eigen::Matrix<double, N, 1>& q) -> R {
    py::gil_scoped_acquire gil;
    if (callbacks->solving && callbacks->state.first_error) {
      throw ModelError(std::string("Chart.") + who + ": an earlier callback failed");
    }
    try {
      return convert(fn(to_numpy(q)));
    } catch (...) {
      if (callbacks->solving && !callbacks->state.first_error) callbacks->state.first_error = std::current_exception();
      throw;
    }
  };
}

template <int N>
ChartManifold make_chart(const py::object& christoffel, const py::object& metric, const std::string& name, bool parallel) {
  using C = manifolds::Chart<N>;
  auto callbacks = std::make_shared<ChartCallbacks>();
  const auto symbols = [](const py::object& value) {
    const Array a = as_array(value, "Chart.christoffel", "result");
    if (a.ndim() != 3 || a.shape(0) != N || a.shape(1) != N || a.shape(2) != N) {
      const std::string n = std::to_string(N);
      throw_invalid("Chart.christoffel", "result", "array of shape " + shape_text(a),
                    "must have shape (" + n + ", " + n + ", " + n + ")");
    }
    typename C::Coefficients c;  // c[i](k, j) = Gamma^k_ij = result[k, i, j]; not-finite marks the domain's end
    const double* data = a.data();
    for (int k = 0; k < N; ++k) {
      for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) c[i](k, j) = data[(k * N + i) * N + j];
      }
    }
    return c;
  };
  typename C::MetricField metric_field;
  if (!metric.is_none()) {
    if (!PyCallable_Check(metric.ptr())) throw_invalid("Chart", "metric", repr_of(metric), "is not callable");
    metric_field = chart_field<N, typename C::Operator>(callbacks, metric, "metric", [](const py::object& value) {
      return to_eigen<typename C::Operator>(value, "Chart.metric", "result");
    });
  }
  if (!PyCallable_Check(christoffel.ptr())) throw_invalid("Chart", "christoffel", repr_of(christoffel), "is not callable");
  C chart(chart_field<N, typename C::Coefficients>(callbacks, christoffel, "christoffel", symbols), std::move(metric_field),
          name, parallel);
  return {std::move(chart), std::move(callbacks)};
}

void bind_chart(py::module_& m) {
  py::class_<ChartManifold> cls(
      m, "Chart",
      "A manifold of your own in one chart: points are coordinates q in an open set of R^m (m = 2 or 3) and the "
      "connection any field of Christoffel symbols q -> Gamma^k_ij(q) (torsion allowed); pieces are coordinate lines, "
      "transport along them is integrated by RK4 (include/cartan/manifolds/chart.hpp).");
  cls.def(py::init([](const py::object& christoffel, const py::object& dim, const py::object& metric,
                      const std::string& name, bool parallel) {
            const int n = number_arg<int>(dim, "Chart", "dim");
            if (n != 2 && n != 3) throw_invalid("Chart", "dim", std::to_string(n), "must be 2 or 3");
            return n == 2 ? make_chart<2>(christoffel, metric, name, parallel)
                          : make_chart<3>(christoffel, metric, name, parallel);
          }),
          py::arg("christoffel"), py::kw_only(), py::arg("dim"), py::arg("metric") = py::none(),
          py::arg("name") = "chart", py::arg("parallel") = false,
          "christoffel(q) -> a (m, m, m) array with christoffel[k, i, j] = Gamma^k_ij at q (as Euclidean); "
          "non-finite values (or an exception) mark points outside the chart. metric(q) -> (m, m), optional (a "
          "metric the connection preserves). parallel: declare nabla T = nabla R = 0 (e.g. constant curvature), "
          "which lets the solver compute the frame components once; only when true.");
  def_manifold_methods(cls, "Chart");
  cls.def("__repr__", [](const ChartManifold& h) {
    return visit_holder(h, [](const auto& c) {
      return "Chart(name=" + std::string(c.name()) + ", dim=" + std::to_string(c.kDim) + ")";
    });
  });
}

}  // namespace

void bind_manifolds(py::module_& m) {
  bind_quadric<Sphere>(m, "Sphere",
                       "The unit sphere S^2 in R^3 with its Levi-Civita connection: points are unit vectors, tangent "
                       "vectors ambient (3,) vectors, Gamma_q(x, y) = q (x . y).")
      .def_static("point", [](const py::object& x) {
        return to_numpy(manifolds::sphere_point(to_eigen<Eigen::Vector3d>(x, "Sphere.point", "x"), "Sphere.point"));
      }, py::arg("x"), "The point of S^2 in the direction of x (x / |x|).");
  bind_quadric<HyperbolicPlane>(
      m, "HyperbolicPlane",
      "The hyperbolic plane H^2 as the upper sheet of q1^2 + q2^2 - q3^2 = -1 in R^3 (Minkowski product), with its "
      "Levi-Civita connection: Gamma_q(x, y) = -q <x, y>.")
      .def_static("point", [](double x1, double x2) { return to_numpy(manifolds::hyperbolic_point(x1, x2)); },
                  py::arg("x1"), py::arg("x2"), "The point (x1, x2, sqrt(1 + x1^2 + x2^2)) of H^2.");
  bind_euclidean(m);
  bind_chart(m);
  bind_group_manifold(m);
}

}  // namespace cartan::python
