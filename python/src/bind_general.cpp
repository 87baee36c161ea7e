// Manifolds with a linear connection (include/cartan/manifolds) and the general
// transported-velocity solve (include/cartan/general/solve.hpp), in their own translation unit.
//
// Python classes: Sphere, HyperbolicPlane (Quadric<+-1>), Euclidean (R^2 or R^3 with constant
// Christoffel symbols: one class over Euclidean<2> and Euclidean<3>) and GroupManifold (one
// class over GroupManifold<G> for SO(3), H3, SE(2), SE(3) with any left-invariant connection).
// Each has the same geometry methods (christoffel, torsion, curvature, step, difference,
// transport_along_step, tangent_basis, ...), bound once by def_manifold_methods.
//
// `_solve_general(manifold, ...)`: general::solve with the vocabulary of cartan.solve. To keep the
// compile time down there is one Lagrangian type per manifold, AnyLagrangian<M>: a type-erased
// KineticPotential<M> (l = 1/2 v^T A v - V(q), V built in (gravity) or a Python callable) or a
// Lagrangian object written in Python. So general::solve is instantiated once per manifold type
// (8 in all). Solves without Python callbacks release the GIL; with them, the GIL is held and the
// first callback error is re-raised after the solver returns (python_models.hpp).

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "bind_group.hpp"
#include "bindings.hpp"
#include "cartan/general/solve.hpp"
#include "cartan/general/verify.hpp"
#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/manifolds/euclidean.hpp"
#include "cartan/manifolds/chart.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "python_models.hpp"
#include "report_dict.hpp"

namespace cartan::python {

namespace {

using manifolds::ComponentMatrixOf;
using manifolds::ComponentsOf;
using manifolds::FrameOf;
using manifolds::HyperbolicPlane;
using manifolds::OperatorOf;
using manifolds::PointOf;
using manifolds::Sphere;
using manifolds::VectorOf;

/// R^2 or R^3 with constant Christoffel symbols: the Python class `Euclidean`.
struct EuclideanManifold {
  std::variant<manifolds::Euclidean<2>, manifolds::Euclidean<3>> m;
};

/// The state of a chart's Python callbacks: the first exception raised during a solve (re-raised
/// after it, with its type and traceback), and whether a solve is running (then later callbacks
/// fail at once, as ModelError, which the solvers pass through).
struct ChartCallbacks {
  CallbackState state;
  bool solving = false;
};

/// A chart of R^2 or R^3 with Christoffel symbols (and optionally a metric) from Python callables:
/// the Python class `Chart`.
struct ChartManifold {
  std::variant<manifolds::Chart<2>, manifolds::Chart<3>> m;
  std::shared_ptr<ChartCallbacks> callbacks;
};

/// A Lie group with a left-invariant connection: the Python class `GroupManifold`.
struct AnyGroupManifold {
  std::variant<manifolds::GroupManifold<groups::SO3>, manifolds::GroupManifold<groups::Heisenberg>,
               manifolds::GroupManifold<groups::SE2>, manifolds::GroupManifold<groups::SE3>>
      m;
};

/// f(manifold) for the C++ manifold a Python manifold object holds.
template <class Holder, class F>
decltype(auto) visit_holder(const Holder& holder, F&& f) {
  if constexpr (requires { holder.m.index(); }) {
    return std::visit(std::forward<F>(f), holder.m);
  } else {
    return std::forward<F>(f)(holder);
  }
}

// ---- arguments --------------------------------------------------------------------------------

/// repr(x) for a message (quoted and cut, as user input).
std::string repr_of(const py::handle& x) { return quote_input(py::repr(x).cast<std::string>()); }

template <class M>
PointOf<M> point_arg(const M& manifold, const py::handle& q, const std::string& where, const char* name) {
  const PointOf<M> p = to_eigen<PointOf<M>>(q, where, name);
  manifold.validate(p, name);
  return p;
}

/// A Python number as T (double or int); throws std::invalid_argument naming it otherwise.
template <class T>
T number_arg(const py::handle& x, const std::string& where, const char* name) {
  try {
    return x.cast<T>();
  } catch (const py::cast_error&) {
    throw_invalid(where, name, repr_of(x), std::is_integral_v<T> ? "is not an integer" : "is not a number");
  }
}

template <class T>
T finite_arg(const py::handle& x, const std::string& where, const char* name) {
  const T value = to_eigen<T>(x, where, name);
  require_finite(value, where, name);
  return value;
}

template <int N>
using Square = Eigen::Matrix<double, N, N>;

/// A (n, n, n) array as n matrices: out[a](b, c) = array[a, b, c].
template <int N>
std::array<Square<N>, N> tensor_arg(const py::handle& obj, const std::string& where, const char* name) {
  const Array a = as_array(obj, where, name);
  if (a.ndim() != 3 || a.shape(0) != N || a.shape(1) != N || a.shape(2) != N) {
    const std::string n = std::to_string(N);
    throw_invalid(where, name, "array of shape " + shape_text(a), "must have shape (" + n + ", " + n + ", " + n + ")");
  }
  std::array<Square<N>, N> out;
  const double* data = a.data();
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      for (int k = 0; k < N; ++k) out[i](j, k) = data[(i * N + j) * N + k];
    }
  }
  for (int i = 0; i < N; ++i) require_finite(out[i], where, name);
  return out;
}

/// n matrices as a (n, n, n) array: array[a, b, c] = in[a](b, c).
template <int N>
py::array_t<double> tensor_numpy(const std::array<Square<N>, N>& in) {
  return to_numpy(std::vector<Square<N>>(in.begin(), in.end()));
}

/// A symmetric positive-definite matrix from a (n, n) array or its (n,) diagonal.
template <int N>
Square<N> matrix_or_diagonal(const py::handle& obj, const std::string& where, const char* name) {
  const Array a = as_array(obj, where, name);
  if (a.ndim() == 1 && a.shape(0) == N) return to_eigen<Eigen::Matrix<double, N, 1>>(a, where, name).asDiagonal();
  if (a.ndim() == 2 && a.shape(0) == N && a.shape(1) == N) return to_eigen<Square<N>>(a, where, name);
  const std::string n = std::to_string(N);
  throw_invalid(where, name, "array of shape " + shape_text(a), "must have shape (" + n + ", " + n + ") or (" + n + ",)");
}

// ---- the manifold classes ---------------------------------------------------------------------

/// The geometry of manifolds/manifold.hpp and geometry.hpp, the same for every class.
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

// ---- Lagrangians ------------------------------------------------------------------------------

/// A Lagrangian of the general problem behind a shared pointer: one type per manifold for every
/// Lagrangian, so that general::solve is instantiated once per manifold.
template <manifolds::ManifoldWithConnection M>
class AnyLagrangian {
 public:
  using Point = PointOf<M>;
  using Vector = VectorOf<M>;
  using Components = ComponentsOf<M>;

  template <general::ManifoldLagrangian<M> L>
  static AnyLagrangian of(L lagrangian) {
    return AnyLagrangian(std::make_shared<const Model<L>>(std::move(lagrangian)));
  }

  double value(double t, const Point& q, const Components& v) const { return impl_->value(t, q, v); }
  Components momentum(double t, const Point& q, const Components& v) const { return impl_->momentum(t, q, v); }
  Components velocity(double t, const Point& q, const Components& mu) const { return impl_->velocity(t, q, mu); }
  Vector point_gradient(double t, const Point& q, const Components& v) const { return impl_->point_gradient(t, q, v); }
  /// The wrapped Lagrangian's second derivatives (its own where it has them: general/lagrangian_hessian.hpp).
  general::LagrangianHessian<M> hessian(const M& manifold, double t, const Point& q, const Components& v) const {
    return impl_->hessian(manifold, t, q, v);
  }

 private:
  struct Interface {
    virtual ~Interface() = default;
    virtual double value(double t, const Point& q, const Components& v) const = 0;
    virtual Components momentum(double t, const Point& q, const Components& v) const = 0;
    virtual Components velocity(double t, const Point& q, const Components& mu) const = 0;
    virtual Vector point_gradient(double t, const Point& q, const Components& v) const = 0;
    virtual general::LagrangianHessian<M> hessian(const M& manifold, double t, const Point& q,
                                                  const Components& v) const = 0;
  };
  template <class L>
  struct Model final : Interface {
    explicit Model(L l) : lagrangian(std::move(l)) {}
    double value(double t, const Point& q, const Components& v) const override { return lagrangian.value(t, q, v); }
    Components momentum(double t, const Point& q, const Components& v) const override {
      return lagrangian.momentum(t, q, v);
    }
    Components velocity(double t, const Point& q, const Components& mu) const override {
      return lagrangian.velocity(t, q, mu);
    }
    Vector point_gradient(double t, const Point& q, const Components& v) const override {
      return lagrangian.point_gradient(t, q, v);
    }
    general::LagrangianHessian<M> hessian(const M& manifold, double t, const Point& q,
                                          const Components& v) const override {
      return general::lagrangian_hessian(manifold, lagrangian, t, q, v);
    }
    L lagrangian;
  };
  explicit AnyLagrangian(std::shared_ptr<const Interface> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const Interface> impl_;
};

/// A Lagrangian written in Python: value(t, q, v), momentum(t, q, v), velocity(t, q, mu) and
/// point_gradient(t, q, v) (an ambient (d,) covector: zeta . x = d/de l(t, step(q, e x), v)).
template <manifolds::ManifoldWithConnection M>
class PythonManifoldLagrangian : public PythonModel {
 public:
  explicit PythonManifoldLagrangian(const py::object& object)
      : PythonModel(object, "Lagrangian", {"value", "momentum", "velocity", "point_gradient"}) {}

  double value(double t, const PointOf<M>& q, const ComponentsOf<M>& v) const { return call<double>(0, t, q, v); }
  ComponentsOf<M> momentum(double t, const PointOf<M>& q, const ComponentsOf<M>& v) const {
    return call<ComponentsOf<M>>(1, t, q, v);
  }
  ComponentsOf<M> velocity(double t, const PointOf<M>& q, const ComponentsOf<M>& mu) const {
    return call<ComponentsOf<M>>(2, t, q, mu);
  }
  VectorOf<M> point_gradient(double t, const PointOf<M>& q, const ComponentsOf<M>& v) const {
    return call<VectorOf<M>>(3, t, q, v);
  }
};

// ---- solve_general ----------------------------------------------------------------------------

/// The arguments of cartan.solve_general as Python gives them.
struct GeneralRequest {
  double T = 1;
  int N = 100;
  py::object q0 = py::none(), qT = py::none(), inertia = py::none(), potential = py::none(),
             potential_gradient = py::none(), gravity = py::none(), lagrangian = py::none(), frame0 = py::none();
  std::string method = "auto", continuation = "none";
  int order = 1;
  double tol = 1e-10;
  int max_iterations = 200;
  py::object v0 = py::none(), Xi0 = py::none(), progress = py::none();
  int samples = 0;
  py::object max_nodes = py::none(), guess = py::none();
};

constexpr const char* kWhere = "cartan.solve_general";

/// The Lagrangian of the request on M; `python` is set when it calls back into Python.
template <class M>
AnyLagrangian<M> request_lagrangian(const M&, const GeneralRequest& r, std::shared_ptr<CallbackState> state,
                                    std::optional<PythonManifoldLagrangian<M>>& python_object, bool& python) {
  constexpr int m = M::kDim;
  using Point = PointOf<M>;
  using Vector = VectorOf<M>;
  if (!r.lagrangian.is_none()) {
    for (const auto& [name, value] : {std::pair<const char*, const py::object*>{"inertia", &r.inertia},
                                      {"potential", &r.potential}, {"potential_gradient", &r.potential_gradient},
                                      {"gravity", &r.gravity}}) {
      if (!value->is_none()) {
        throw_invalid(kWhere, name, repr_of(*value), "does not apply with a lagrangian object (it defines l itself)");
      }
    }
    python = true;
    python_object.emplace(r.lagrangian);
    return AnyLagrangian<M>::of(*python_object);
  }
  const Square<m> inertia = r.inertia.is_none() ? Square<m>::Identity().eval()
                                                : matrix_or_diagonal<m>(r.inertia, kWhere, "inertia");
  if (!r.gravity.is_none()) {
    const double G = number_arg<double>(r.gravity, kWhere, "gravity");
    require_finite(G, kWhere, "gravity");
    if constexpr (!std::is_same_v<M, Sphere>) {
      throw_invalid(kWhere, "gravity", format_value(G),
                    "applies to the Sphere only (give potential and potential_gradient)");
    } else {
      if (!r.potential.is_none()) {
        throw_invalid(kWhere, "potential", repr_of(r.potential), "and gravity exclude each other");
      }
      return AnyLagrangian<M>::of(
          general::KineticPotential<M>::with_linear_potential(inertia, Vector(0, 0, G)));
    }
  }
  if (r.potential.is_none() != r.potential_gradient.is_none()) {
    const bool has_v = !r.potential.is_none();
    throw_invalid(kWhere, has_v ? "potential_gradient" : "potential", "None",
                  has_v ? "must be given with potential (both or neither)"
                        : "must be given with potential_gradient (both or neither)");
  }
  if (r.potential.is_none()) return AnyLagrangian<M>::of(general::KineticPotential<M>(inertia));
  for (const auto& [name, fn] : {std::pair<const char*, const py::object*>{"potential", &r.potential},
                                 {"potential_gradient", &r.potential_gradient}}) {
    if (!PyCallable_Check(fn->ptr())) throw_invalid(kWhere, name, repr_of(*fn), "is not callable");
  }
  python = true;
  typename general::KineticPotential<M>::Potential potential = [state, fn = r.potential](const Point& q) {
    return guarded_callback(*state, "potential", [&] {
      const double value = FromPython<double>::convert(fn(to_numpy(q)), "potential");
      if (!std::isfinite(value) && q.allFinite()) {
        throw ModelError("potential returned a non-finite value at q = " + format_value(q));
      }
      return value;
    });
  };
  typename general::KineticPotential<M>::PotentialGradient gradient = [state, fn = r.potential_gradient](const Point& q) {
    return guarded_callback(*state, "potential_gradient", [&] {
      const Vector value = FromPython<Vector>::convert(fn(to_numpy(q)), "potential_gradient");
      if (!value.allFinite() && q.allFinite()) {
        throw ModelError("potential_gradient returned a non-finite value at q = " + format_value(q));
      }
      return value;
    });
  };
  return AnyLagrangian<M>::of(general::KineticPotential<M>(inertia, std::move(potential), std::move(gradient)));
}

/// Runs a solve or check f() on a manifold whose geometry may call Python (`chart` non-null, with
/// the GIL held): the chart's first callback error is re-raised after it, in place of whatever
/// the solver made of it.
template <class F>
auto run_on_chart(ChartCallbacks* chart, F&& f) {
  if (chart == nullptr) return f();
  chart->state.first_error = nullptr;
  chart->solving = true;
  struct Done {
    ChartCallbacks* c;
    ~Done() { c->solving = false; }
  } done{chart};
  return run_with_callbacks(chart->state, std::forward<F>(f));
}

/// `name` of `object` (an attribute), or an error naming what `object` should be.
inline py::object field_of(const py::object& object, const char* name, const char* where, const char* what) {
  if (!py::hasattr(object, name)) {
    throw_invalid(where, what, repr_of(object), std::string("has no field ") + name + " (give a GeneralSolveResult)");
  }
  return object.attr(name);
}

/// The trajectory (t, q, frame, v, mu, Xi) of a GeneralSolveResult-like object, each entry checked
/// (points valid on the manifold, finite components) with errors naming `what`.
template <class M>
general::GeneralTrajectory<M> trajectory_of(const M& manifold, const py::object& object, const char* where,
                                            const char* what) {
  const auto field = [&](const char* name) -> py::sequence { return field_of(object, name, where, what); };
  const py::sequence times = field("t"), q = field("q"), frames = field("frame"), v = field("v"), mu = field("mu"),
                     Xi = field("Xi");
  general::GeneralTrajectory<M> x;
  for (const auto& time : times) x.t.push_back(number_arg<double>(time, where, "t"));
  const std::size_t n = x.t.size();
  if (py::len(q) != n || py::len(frames) != n || py::len(v) != n || py::len(mu) != n || py::len(Xi) != n) {
    throw_invalid(where, what, "(" + std::to_string(n) + " times)", "needs q, frame, v, mu and Xi at every time");
  }
  // Built by append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string here.
  const auto name = [what](const char* field_name, std::size_t k) {
    std::string s(what);
    s.append(".").append(field_name).append("[").append(std::to_string(k)).append("]");
    return s;
  };
  for (std::size_t k = 0; k < n; ++k) {
    x.q.push_back(point_arg(manifold, q[k], where, name("q", k).c_str()));
    x.frame.push_back(to_eigen<FrameOf<M>>(frames[k], where, name("frame", k)));
    x.v.push_back(to_eigen<ComponentsOf<M>>(v[k], where, name("v", k)));
    x.mu.push_back(to_eigen<ComponentsOf<M>>(mu[k], where, name("mu", k)));
    x.Xi.push_back(to_eigen<ComponentMatrixOf<M>>(Xi[k], where, name("Xi", k)));
  }
  return x;
}

template <class M>
py::dict solve_on(const M& manifold, const GeneralRequest& r, ChartCallbacks* chart) {
  using Problem = general::GeneralProblem<M, AnyLagrangian<M>>;
  const std::string where = kWhere;
  auto state = std::make_shared<CallbackState>();
  std::optional<PythonManifoldLagrangian<M>> python_object;
  bool python = false;
  Problem problem{manifold, request_lagrangian(manifold, r, state, python_object, python), r.T, r.N,
                  point_arg(manifold, r.q0, where, "q0"), point_arg(manifold, r.qT, where, "qT"), std::nullopt};
  if (!r.frame0.is_none()) problem.frame0 = to_eigen<FrameOf<M>>(r.frame0, where, "frame0");

  transported::SolveOptions options;
  options.method = parse_enum<transported::Method>(r.method, where);
  options.continuation = parse_enum<transported::Continuation>(r.continuation, where);
  if (r.order != 1 && r.order != 2) throw_invalid(where, "order", std::to_string(r.order), "must be 1 or 2");
  options.order = r.order == 2 ? transported::SchemeOrder::Second : transported::SchemeOrder::First;
  options.tol = r.tol;
  options.max_iterations = r.max_iterations;
  options.samples = r.samples;
  if (!r.max_nodes.is_none()) options.max_nodes = number_arg<int>(r.max_nodes, where, "max_nodes");
  options.monitor = python_monitor(r.progress).stage("general shooting");  // copied here, with the GIL
  general::GeneralGuess<M> guess;
  if (!r.v0.is_none()) guess.v0 = finite_arg<ComponentsOf<M>>(r.v0, where, "v0");
  if (!r.Xi0.is_none()) guess.Xi0 = finite_arg<ComponentMatrixOf<M>>(r.Xi0, where, "Xi0");
  if (!r.guess.is_none()) guess.trajectory = trajectory_of(manifold, r.guess, kWhere, "guess");

  const auto run = [&] { return general::solve(problem, options, guess); };
  const CallbackState& callbacks = python_object ? python_object->state() : *state;
  std::optional<general::GeneralSolution<M>> solved;
  if (python || chart != nullptr) {
    solved.emplace(run_on_chart(chart, [&] { return run_with_callbacks(callbacks, run); }));
  } else {
    py::gil_scoped_release release;
    solved.emplace(run());
  }
  const general::GeneralSolution<M>& s = *solved;
  py::dict d;
  d["status"] = std::string(to_string(s.status));
  d["message"] = s.message;
  d["success"] = s.converged();
  d["method"] = std::string(to_string(s.method));
  d["order"] = s.order;
  d["branch"] = s.branch;
  d["manifold"] = std::string(manifold.name());
  d["T"] = problem.T;
  d["N"] = problem.N;
  d["q0"] = to_numpy(problem.q0);
  d["qT"] = to_numpy(problem.qT);
  d["tol"] = options.tol;
  const auto& tr = s.trajectory;
  d["t"] = to_numpy(tr.t);
  d["q"] = to_numpy(tr.q);
  d["frame"] = to_numpy(tr.frame);
  d["v"] = to_numpy(tr.v);
  d["mu"] = to_numpy(tr.mu);
  d["Xi"] = to_numpy(tr.Xi);
  d["v0"] = to_numpy(s.v0);
  d["Xi0"] = to_numpy(s.Xi0);
  d["terminal_error"] = s.terminal_error;
  d["xi_terminal"] = s.xi_terminal;
  d["iterations"] = s.iterations;
  d["sweeps"] = s.sweeps;
  d["residual_history"] = to_numpy(s.residual_history);
  d["solve_time"] = s.solve_time_s;
  add_collocation_fields(d, s.collocation);
  return d;
}

/// The library's general verifier (general/verify.hpp) on `result` (any object with T, q0, qT,
/// tol, order, status, t, q, frame, v, mu, Xi, e.g. a GeneralSolveResult) for the Lagrangian of
/// the request (as solve_general takes it).
template <class M>
py::dict verify_on(const M& manifold, const GeneralRequest& r, const py::object& result, ChartCallbacks* chart) {
  constexpr const char* where = "cartan.verify_general";
  const auto field = [&](const char* name) { return field_of(result, name, where, "result"); };
  const Status status = parse_enum<Status>(py::cast<std::string>(field("status")), where);
  if (py::len(field("t")) == 0 && status != Status::Converged) return report_dict(verify::unchecked_failure(status));
  const general::GeneralTrajectory<M> x = trajectory_of(manifold, result, where, "result");
  if (x.t.empty()) throw_invalid(where, "result.t", "(empty)", "needs the samples of a solution");
  auto state = std::make_shared<CallbackState>();
  std::optional<PythonManifoldLagrangian<M>> python_object;
  bool python = false;
  const general::GeneralProblem<M, AnyLagrangian<M>> problem{
      manifold, request_lagrangian(manifold, r, state, python_object, python), number_arg<double>(field("T"), where, "T"),
      static_cast<int>(std::max<std::size_t>(x.t.size(), 2) - 1), point_arg(manifold, field("q0"), where, "q0"),
      point_arg(manifold, field("qT"), where, "qT"), x.frame.front()};
  const int order = py::cast<int>(field("order"));
  const double tol = number_arg<double>(field("tol"), where, "tol");
  const auto run = [&] { return general::verify_general(problem, x, order, tol, status); };
  if (python || chart != nullptr) {
    return report_dict(
        run_on_chart(chart, [&] { return run_with_callbacks(python_object ? python_object->state() : *state, run); }));
  }
  return report_dict(run());
}

/// f(manifold, chart callbacks) for the C++ manifold behind a Python manifold object; the
/// callbacks are those of a cartan.Chart, null for the built-in manifolds.
template <class F>
py::dict visit_manifold(const py::handle& object, F&& f) {
  const auto built_in = [&](const auto& m) { return f(m, static_cast<ChartCallbacks*>(nullptr)); };
  if (py::isinstance<Sphere>(object)) return built_in(object.cast<const Sphere&>());
  if (py::isinstance<HyperbolicPlane>(object)) return built_in(object.cast<const HyperbolicPlane&>());
  if (py::isinstance<EuclideanManifold>(object)) return visit_holder(object.cast<const EuclideanManifold&>(), built_in);
  if (py::isinstance<AnyGroupManifold>(object)) return visit_holder(object.cast<const AnyGroupManifold&>(), built_in);
  if (py::isinstance<ChartManifold>(object)) {
    const auto& chart = object.cast<const ChartManifold&>();
    return visit_holder(chart, [&](const auto& m) { return f(m, chart.callbacks.get()); });
  }
  throw_invalid(kWhere, "manifold", repr_of(object),
                "is not a manifold (cartan.Sphere, HyperbolicPlane, Euclidean, GroupManifold, Chart)");
}

}  // namespace

void bind_general(py::module_& m) {
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

  py::class_<GeneralRequest>(m, "_GeneralRequest")
      .def(py::init<>())
      .def_readwrite("T", &GeneralRequest::T)
      .def_readwrite("N", &GeneralRequest::N)
      .def_readwrite("q0", &GeneralRequest::q0)
      .def_readwrite("qT", &GeneralRequest::qT)
      .def_readwrite("inertia", &GeneralRequest::inertia)
      .def_readwrite("potential", &GeneralRequest::potential)
      .def_readwrite("potential_gradient", &GeneralRequest::potential_gradient)
      .def_readwrite("gravity", &GeneralRequest::gravity)
      .def_readwrite("lagrangian", &GeneralRequest::lagrangian)
      .def_readwrite("frame0", &GeneralRequest::frame0)
      .def_readwrite("method", &GeneralRequest::method)
      .def_readwrite("continuation", &GeneralRequest::continuation)
      .def_readwrite("order", &GeneralRequest::order)
      .def_readwrite("tol", &GeneralRequest::tol)
      .def_readwrite("max_iterations", &GeneralRequest::max_iterations)
      .def_readwrite("v0", &GeneralRequest::v0)
      .def_readwrite("Xi0", &GeneralRequest::Xi0)
      .def_readwrite("progress", &GeneralRequest::progress)
      .def_readwrite("samples", &GeneralRequest::samples)
      .def_readwrite("max_nodes", &GeneralRequest::max_nodes)
      .def_readwrite("guess", &GeneralRequest::guess);
  m.def("_solve_general", [](const py::object& manifold, const GeneralRequest& request) {
    return visit_manifold(manifold, [&](const auto& mf, ChartCallbacks* chart) { return solve_on(mf, request, chart); });
  }, py::arg("manifold"), py::arg("request"));
  m.def("_verify_general", [](const py::object& manifold, const GeneralRequest& request, const py::object& result) {
    return visit_manifold(manifold, [&](const auto& mf, ChartCallbacks* chart) {
      return verify_on(mf, request, result, chart);
    });
  }, py::arg("manifold"), py::arg("request"), py::arg("result"));
}

}  // namespace cartan::python
