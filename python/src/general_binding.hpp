#pragma once
// The general solve of the Python module (bind_general.cpp) on each manifold type: solve_on and
// verify_on with their Lagrangians and arguments, and the manifold classes' holders, argument
// helpers and geometry methods (bind_manifolds.cpp, bind_group_manifold.cpp). Every Lagrangian
// goes behind the erased type, whose solve, verify and along the library compiles once per manifold
// behind the api's door for problems given as objects (api/erased.hpp): this unit only converts
// the arguments and the result.

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "bind_group.hpp"
#include "bindings.hpp"
#include "cartan/api/erased.hpp"
#include "cartan/mechanics/manifold_compiled.hpp"
#include "python_models.hpp"
#include "report_dict.hpp"

namespace cartan::python::general_binding {

template <groups::LieGroup G>
using OnGroup = manifolds::GroupManifold<G>;

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

/// The state of a chart's Python callbacks: whether a solve is running; during one, an Exception
/// raised by a field marks its point outside the chart (as NaN does: the solvers step back), and
/// the first is described in `outside` for the message of a solve that fails; any other error
/// (KeyboardInterrupt, an error converting the result) is the first error, re-raised after the
/// solve with its type and traceback (later callbacks then fail at once, as ModelError, which the
/// solvers pass through).
struct ChartCallbacks {
  CallbackState state;
  bool solving = false;
  std::string outside;
};

/// A chart of R^2 or R^3 with Christoffel symbols (and optionally a metric) from Python callables:
/// the Python class `Chart`.
struct ChartManifold {
  std::variant<manifolds::Chart<2>, manifolds::Chart<3>> m;
  std::shared_ptr<ChartCallbacks> callbacks;
};

/// A Lie group with a left-invariant connection: the Python class `GroupManifold`.
struct AnyGroupManifold {
  std::variant<OnGroup<groups::SO3>, OnGroup<groups::Heisenberg>,
               OnGroup<groups::SE2>, OnGroup<groups::SE3>>
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

template <class M>
PointOf<M> point_arg(const M& manifold, const py::handle& q, const std::string& where, const char* name) {
  const PointOf<M> p = to_eigen<PointOf<M>>(q, where, name);
  if constexpr (requires { typename M::Group; }) {
    return checked_endpoint<typename M::Group>(p, where, name);  // as a group model's endpoint
  } else {
    manifold.validate(p, name);
    return p;
  }
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

template <class M>
api::Samples samples_of(const M& manifold, const py::object& object, const char* where, const char* what);

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
  // `_dense(result, method, times)`: the library's dense output (api/erased.hpp) of a result on
  // this manifold at the 1-d array `times`, as a dict of q, frame, v, mu, Xi with one row per time.
  cls.def("_dense", [](const Holder& h, const py::object& result, const std::string& method, const py::object& times) {
    return visit_holder(h, [&](const auto& m) {
      using M = std::decay_t<decltype(m)>;
      constexpr const char* where = "Result.sol";
      const api::Samples x = samples_of(m, result, where, "result");
      const Array t = as_array(times, where, "t");
      api::Samples d = api::dense(m, x, parse_enum<cartan::Method>(method, where), std::vector<double>(t.data(), t.data() + t.size()),
                                  where);
      py::dict out;
      out["q"] = rows_to_numpy<PointOf<M>>(std::move(d.points));
      out["frame"] = rows_to_numpy<FrameOf<M>>(std::move(d.frames));
      out["v"] = rows_to_numpy<ComponentsOf<M>>(std::move(d.v));
      out["mu"] = rows_to_numpy<ComponentsOf<M>>(std::move(d.mu));
      out["Xi"] = rows_to_numpy<ComponentMatrixOf<M>>(std::move(d.aux));
      return out;
    });
  }, py::arg("result"), py::arg("method"), py::arg("times"));
  cls.def("tangent_basis", [name](const Holder& h, const py::object& q) {
    return visit_holder(h, [&](const auto& m) { return to_numpy(m.tangent_basis(point_arg(m, q, name + ".tangent_basis", "q"))); });
  }, py::arg("q"), "A (d, m) basis of T_qQ (orthonormal where there is a metric).");
  cls.def("default_frame", [name](const Holder& h, const py::object& q0, const py::object& qT) {
    return visit_holder(h, [&](const auto& m) {
      const std::string where = name + ".default_frame";
      return to_numpy(manifolds::default_frame(m, point_arg(m, q0, where, "q0"), point_arg(m, qT, where, "qT")));
    });
  }, py::arg("q0"), py::arg("qT"),
     "The default frame0 of a problem from q0 to qT, (d, m): on the sphere and the hyperbolic plane e1 the unit "
     "tangent along the minimal geodesic towards qT and e2 = J (q0 x e1) (where that is undefined, equal or "
     "antipodal endpoints, tangent_basis(q0), and a Lagrangian that depends on the frame needs frame0); "
     "elsewhere tangent_basis(q0).");
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

// ---- Lagrangians ------------------------------------------------------------------------------

/// A Lagrangian written in Python: value(t, q, v), momentum(t, q, v), velocity(t, q, mu) and
/// point_gradient(t, q, v) (an ambient (d,) covector: zeta . x = d/de l(t, step(q, e x), v)); the
/// attribute `frame_invariant = True` (or a method returning True) says that l does not depend on
/// the orthonormal frame (mechanics::frame_invariant_of), so that the fallback frame serves it.
template <manifolds::ManifoldWithConnection M>
class PythonManifoldLagrangian : public PythonModel {
 public:
  explicit PythonManifoldLagrangian(const py::object& object)
      : PythonModel(object, "Lagrangian", {"value", "momentum", "velocity", "point_gradient"}),
        frame_invariant_(declares_frame_invariance(object)) {}

  /// What the object declares; without a declaration it is taken to depend on the frame.
  bool frame_invariant() const { return frame_invariant_; }

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

 private:
  static bool declares_frame_invariance(const py::object& object) {
    if (!py::hasattr(object, "frame_invariant")) return false;
    py::object declared = object.attr("frame_invariant");
    if (PyCallable_Check(declared.ptr())) declared = declared();
    return py::bool_(declared);
  }
  bool frame_invariant_;
};

// ---- solve_general ----------------------------------------------------------------------------

/// The arguments of cartan.solve_general as Python gives them.
/// cartan.solve_general's problem and guesses; its options are the library's words
/// (principle/options.hpp), whose defaults stand for every keyword Python leaves at None.
struct GeneralRequest : OptionWords {
  double T = 1;
  int N = 100;
  py::object q0 = py::none(), qT = py::none(), inertia = py::none(), potential = py::none(),
             potential_gradient = py::none(), gravity = py::none(), lagrangian = py::none(), frame0 = py::none();
  py::object v0 = py::none(), Xi0 = py::none(), progress = py::none();
  py::object guess = py::none();
};

inline constexpr const char* kWhere = "cartan.solve";

/// The spaces whose points are vectors with a vertical last axis, where gravity V = G q[last]
/// applies (api/spaces.hpp, SpaceInfo::gravity): the quadrics and Euclidean space.
template <class M>
constexpr bool kVerticalAxis = std::is_same_v<M, Sphere> || std::is_same_v<M, HyperbolicPlane> ||
                               requires(const M& x) { x.coefficients(); };

/// The Lagrangian of the request on M; `python` is set when it calls back into Python.
template <class M>
general::ErasedLagrangian<M> request_lagrangian(const M&, const GeneralRequest& r, std::shared_ptr<CallbackState> state,
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
    return general::ErasedLagrangian<M>(*python_object);
  }
  const Square<m> inertia = r.inertia.is_none() ? Square<m>::Identity().eval()
                                                : matrix_or_diagonal<m>(r.inertia, kWhere, "inertia");
  if (!r.gravity.is_none()) {
    const double G = number_arg<double>(r.gravity, kWhere, "gravity");
    require_finite(G, kWhere, "gravity");
    if constexpr (!kVerticalAxis<M>) {
      throw_invalid(kWhere, "gravity", format_value(G),
                    "applies to the sphere, the hyperbolic plane and Euclidean space only (V = G q[last]; give potential "
                    "and potential_gradient)");
    } else {
      if (!r.potential.is_none()) {
        throw_invalid(kWhere, "potential", repr_of(r.potential), "and gravity exclude each other");
      }
      return general::erased_particle_in_linear_potential<M>(inertia, Vector(G * Vector::Unit(Vector::RowsAtCompileTime - 1)));
    }
  }
  if (r.potential.is_none() != r.potential_gradient.is_none()) {
    const bool has_v = !r.potential.is_none();
    throw_invalid(kWhere, has_v ? "potential_gradient" : "potential", "None",
                  has_v ? "must be given with potential (both or neither)"
                        : "must be given with potential_gradient (both or neither)");
  }
  if (r.potential.is_none()) return general::erased_particle<M>(inertia);
  for (const auto& [name, fn] : {std::pair<const char*, const py::object*>{"potential", &r.potential},
                                 {"potential_gradient", &r.potential_gradient}}) {
    if (!PyCallable_Check(fn->ptr())) throw_invalid(kWhere, name, repr_of(*fn), "is not callable");
  }
  python = true;
  general::ParticlePotential<M> potential = [state, fn = r.potential](const Point& q) {
    return guarded_callback(*state, "potential", [&] {
      const double value = FromPython<double>::convert(fn(to_numpy(q)), "potential");
      if (!std::isfinite(value) && q.allFinite()) {
        throw ModelError("potential returned a non-finite value at q = " + format_value(q));
      }
      return value;
    });
  };
  general::ParticleGradient<M> gradient = [state, fn = r.potential_gradient](const Point& q) {
    return guarded_callback(*state, "potential_gradient", [&] {
      const Vector value = FromPython<Vector>::convert(fn(to_numpy(q)), "potential_gradient");
      if (!value.allFinite() && q.allFinite()) {
        throw ModelError("potential_gradient returned a non-finite value at q = " + format_value(q));
      }
      return value;
    });
  };
  return general::erased_particle<M>(inertia, std::move(potential), std::move(gradient));
}

/// Runs a solve or check f() on a manifold whose geometry may call Python (`chart` non-null, with
/// the GIL held): the chart's first callback error is re-raised after it, in place of whatever
/// the solver made of it.
template <class F>
auto run_on_chart(ChartCallbacks* chart, F&& f) {
  if (chart == nullptr) return f();
  chart->state.first_error = nullptr;
  chart->outside.clear();
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
    throw_invalid(where, what, repr_of(object), std::string("has no field ") + name + " (give a cartan.Result)");
  }
  return object.attr(name);
}

/// The samples (t, q, frame, v, mu, Xi as api::Samples, rows of numbers) of a cartan.Result-like
/// object, each field read as a whole array (to_rows: one shape check, no Python object per row)
/// and each point checked on the manifold, with errors naming `what`.
template <class M>
api::Samples samples_of(const M& manifold, const py::object& object, const char* where, const char* what) {
  // Built by append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string here.
  const auto name = [what](const char* field_name) { return std::string(what).append(".").append(field_name); };
  const auto field = [&](const char* field_name) { return field_of(object, field_name, where, what); };
  api::Samples x;
  const Array t = as_array(field("t"), where, name("t"));
  if (t.ndim() != 1) throw_invalid(where, name("t"), "array of shape " + shape_text(t), "must be one-dimensional");
  x.t = Eigen::Map<const Eigen::VectorXd>(t.data(), t.shape(0));
  x.points = to_rows<PointOf<M>>(field("q"), where, name("q"));
  x.frames = to_rows<FrameOf<M>>(field("frame"), where, name("frame"));
  x.v = to_rows<ComponentsOf<M>>(field("v"), where, name("v"));
  x.mu = to_rows<ComponentsOf<M>>(field("mu"), where, name("mu"));
  x.aux = to_rows<ComponentMatrixOf<M>>(field("Xi"), where, name("Xi"));
  const Eigen::Index n = x.t.size();
  if (x.points.rows() != n || x.frames.rows() != n || x.v.rows() != n || x.mu.rows() != n || x.aux.rows() != n) {
    throw_invalid(where, what, "(" + std::to_string(n) + " times)", "needs q, frame, v, mu and Xi at every time");
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    manifold.validate(api::value_of_row<PointOf<M>>(x.points, k), name("q").append("[").append(std::to_string(k)).append("]"));
  }
  return x;
}

/// A request on M as solve_on poses it: the problem (the request's Lagrangian, the points checked
/// on M, frame0), the options and the guess. Not movable: the erased Lagrangian may refer to the
/// Python object held here.
template <class M>
struct PosedRequest {
  std::shared_ptr<CallbackState> state = std::make_shared<CallbackState>();
  std::optional<PythonManifoldLagrangian<M>> python_object;
  bool python = false;
  api::ManifoldObjectProblem<M> problem;
  cartan::SolveOptions options;
  api::Guess guess;

  PosedRequest(const M& manifold, const GeneralRequest& r)
      : problem{manifold, request_lagrangian(manifold, r, state, python_object, python), r.T, r.N,
                point_arg(manifold, r.q0, kWhere, "q0"), point_arg(manifold, r.qT, kWhere, "qT"), std::nullopt},
        options(solve_options(r, kWhere)) {
    // without frame0 the problem's validation refuses the fallback frame where the Lagrangian depends on it
    if (!r.frame0.is_none()) problem.frame0 = to_eigen<FrameOf<M>>(r.frame0, kWhere, "frame0");
    if (!r.v0.is_none()) guess.v0 = models::element_numbers(finite_arg<ComponentsOf<M>>(r.v0, kWhere, "v0"));
    if (!r.Xi0.is_none()) guess.Xi0 = models::element_numbers(finite_arg<ComponentMatrixOf<M>>(r.Xi0, kWhere, "Xi0"));
    if (!r.guess.is_none()) guess.trajectory = samples_of(manifold, r.guess, kWhere, "guess");
  }
  PosedRequest(const PosedRequest&) = delete;
  PosedRequest& operator=(const PosedRequest&) = delete;
};

/// What a solve of the request would refuse before it starts (the problem's and the options'
/// validation, the arguments' conversions), without solving: cartan.sweep's check of a problem.
template <class M>
void validate_on(const M& manifold, const GeneralRequest& r) {
  const PosedRequest<M> posed(manifold, r);
  api::validate(posed.problem, posed.options, posed.guess, kWhere);
}

template <class M>
py::dict solve_on(const M& manifold, const GeneralRequest& r, ChartCallbacks* chart) {
  PosedRequest<M> posed(manifold, r);
  const api::ManifoldObjectProblem<M>& problem = posed.problem;
  cartan::SolveOptions& options = posed.options;
  options.monitor = python_monitor(r.progress).stage("general shooting");  // copied here, with the GIL
  // The solve, with what the result carries along it (api::solve, SolveOutputs::along): a result
  // stopped on request has its samples only (as a group model's SolveResult).
  const auto run = [&] { return api::solve(problem, options, posed.guess, {.along = true}, kWhere); };
  const CallbackState& callbacks = posed.python_object ? posed.python_object->state() : *posed.state;
  std::optional<api::Result> solved;
  if (posed.python || chart != nullptr) {
    solved.emplace(run_on_chart(chart, [&] { return run_with_callbacks(callbacks, run); }));
  } else {
    py::gil_scoped_release release;
    solved.emplace(run());
  }
  api::Result& s = *solved;  // its samples move into the arrays
  if (chart != nullptr && !chart->outside.empty() && !s.converged()) {
    s.message += " (" + chart->outside + ", treated as outside the chart)";
  }
  py::dict d;
  add_core_fields(d, s);
  d["manifold"] = std::string(manifold.name());
  d["T"] = problem.T;
  d["N"] = problem.N;
  d["q0"] = to_numpy(problem.q0);
  d["qT"] = to_numpy(problem.qT);
  d["tol"] = options.tol;
  api::Samples& x = s.samples;
  d["t"] = to_numpy(x.t);
  d["q"] = rows_to_numpy<PointOf<M>>(std::move(x.points));
  d["frame"] = rows_to_numpy<FrameOf<M>>(std::move(x.frames));
  d["v"] = rows_to_numpy<ComponentsOf<M>>(std::move(x.v));
  d["mu"] = rows_to_numpy<ComponentsOf<M>>(std::move(x.mu));
  d["Xi"] = rows_to_numpy<ComponentMatrixOf<M>>(std::move(x.aux));
  d["v0"] = to_numpy(s.v0);
  d["Xi0"] = to_numpy(api::value_of_row<ComponentMatrixOf<M>>(s.aux0.transpose(), 0));
  d["iterations"] = s.inner_iterations;
  // u, energy, cumulative_action (None without along: stopped on request, or fewer than two samples)
  const py::object none = py::none();
  std::optional<api::Along>& along = s.along;
  d["action"] = s.action;
  d["u"] = along ? py::object(rows_to_numpy<VectorOf<M>>(std::move(along->u))) : none;
  d["energy"] = along ? py::object(to_numpy(along->energy)) : none;
  d["cumulative_action"] = along ? py::object(to_numpy(along->cumulative_action)) : none;
  return d;
}

/// What a result file does not hold and the library computes along the samples (api::along:
/// frame, u, energy, cumulative_action, action) of the fields of a loaded manifold result (t, q, v,
/// T, q0, qT, frame0 as rows) for the request's Lagrangian; with `named_only` (a Lagrangian defined
/// in Python, which the file only names) the frame and u, energy and the action None and NaN.
template <class M>
py::dict along_on(const M& manifold, const GeneralRequest& r, const py::dict& fields, bool named_only) {
  constexpr const char* where = "cartan.load";
  auto state = std::make_shared<CallbackState>();
  std::optional<PythonManifoldLagrangian<M>> python_object;
  bool python = false;
  api::Samples x;
  const Array t = as_array(fields["t"], where, "t");
  x.t = Eigen::Map<const Eigen::VectorXd>(t.data(), t.shape(0));
  x.points = to_rows<PointOf<M>>(fields["q"], where, "q");
  x.v = to_rows<ComponentsOf<M>>(fields["v"], where, "v");
  const api::ManifoldObjectProblem<M> problem{
      manifold, request_lagrangian(manifold, r, state, python_object, python), number_arg<double>(fields["T"], where, "T"),
      number_arg<int>(fields["N"], where, "N"), point_arg(manifold, fields["q0"], where, "q0"),
      point_arg(manifold, fields["qT"], where, "qT"), to_eigen<FrameOf<M>>(fields["frame0"], where, "frame0")};
  api::Along along = api::along(problem, x, where);  // empty tables below two samples
  const py::object none = py::none();
  const bool known = !named_only && along.energy.size() > 0;
  py::dict d;
  d["frame"] = along.frames.rows() == 0 ? none : py::object(rows_to_numpy<FrameOf<M>>(std::move(along.frames)));
  d["u"] = along.u.rows() == 0 ? none : py::object(rows_to_numpy<VectorOf<M>>(std::move(along.u)));
  d["energy"] = known ? py::object(to_numpy(along.energy)) : none;
  d["cumulative_action"] = known ? py::object(to_numpy(along.cumulative_action)) : none;
  d["action"] = known ? along.cumulative_action(along.cumulative_action.size() - 1) : std::numeric_limits<double>::quiet_NaN();
  return d;
}

/// The library's general verifier (api::verify) on `result` (any object with T, q0, qT,
/// tol, order, status, t, q, frame, v, mu, Xi, e.g. a cartan.Result) for the Lagrangian of
/// the request (as solve_general takes it).
template <class M>
py::dict verify_on(const M& manifold, const GeneralRequest& r, const py::object& result, ChartCallbacks* chart) {
  constexpr const char* where = "cartan.verify_general";
  const auto field = [&](const char* name) { return field_of(result, name, where, "result"); };
  const Status status = parse_enum<Status>(py::cast<std::string>(field("status")), where);
  if (py::len(field("t")) == 0 && status != Status::Converged) return report_dict(verify::unchecked_failure(status));
  api::Samples x;
  try {
    x = samples_of(manifold, result, where, "result");
  } catch (const std::invalid_argument& e) {
    if (status == Status::Converged) throw;
    return report_dict(verify::unchecked_failure(status, e.what()));  // a diverged iterate (verify_general)
  }
  if (x.t.size() == 0) throw_invalid(where, "result.t", "(empty)", "needs the samples of a solution");
  auto state = std::make_shared<CallbackState>();
  std::optional<PythonManifoldLagrangian<M>> python_object;
  bool python = false;
  // N and the frame at q0 from the samples (api::verify)
  const api::ManifoldObjectProblem<M> problem{manifold, request_lagrangian(manifold, r, state, python_object, python),
                                              number_arg<double>(field("T"), where, "T"), 1,
                                              point_arg(manifold, field("q0"), where, "q0"),
                                              point_arg(manifold, field("qT"), where, "qT"), std::nullopt};
  const int order = py::cast<int>(field("order"));
  const double tol = number_arg<double>(field("tol"), where, "tol");
  const auto run = [&] { return api::verify(problem, x, order, tol, status, where); };
  if (python || chart != nullptr) {
    return report_dict(
        run_on_chart(chart, [&] { return run_with_callbacks(python_object ? python_object->state() : *state, run); }));
  }
  return report_dict(run());
}

/// The point the seeded samples of cartan.check_lagrangian are taken around when none is given: the
/// quadrics' pole (0, 0, 1), the origin of R^m, the identity of a group; a chart has none (its
/// domain is the user's), so `q` must be given.
template <class M>
PointOf<M> default_sample_point(const M& manifold, const py::object& q, const std::string& where) {
  if (!q.is_none()) return point_arg(manifold, q, where, "q");
  if constexpr (std::is_same_v<M, Sphere> || std::is_same_v<M, manifolds::HyperbolicPlane>) {
    return PointOf<M>(0, 0, 1);
  } else if constexpr (requires { typename M::Group; }) {
    return M::Group::identity();
  } else if constexpr (requires(const M& x) { x.coefficients(); }) {
    return PointOf<M>::Zero();  // Euclidean
  } else {
    throw_invalid(where, "q", "None", "must be given on a Chart (a point of its domain the samples are taken around)");
  }
}

/// The samples of cartan.check_lagrangian on a manifold: a count (seeded samples around `q`) or a
/// sequence of (t, q, v) triples.
template <class M>
std::vector<general::ManifoldLagrangianSample<M>> manifold_check_samples(const M& manifold, const py::object& samples,
                                                                         mechanics::CheckLagrangianOptions options,
                                                                         const py::object& q) {
  const std::string where = "cartan.check_lagrangian";
  if (py::isinstance<py::int_>(samples) && !py::isinstance<py::bool_>(samples)) {
    options.samples = samples.cast<int>();
    return general::lagrangian_samples(manifold, default_sample_point(manifold, q, where), options);
  }
  if (!py::isinstance<py::sequence>(samples) || py::isinstance<py::str>(samples)) {
    throw_invalid(where, "samples", repr_of(samples), "is neither a count nor a sequence of (t, q, v)");
  }
  std::vector<general::ManifoldLagrangianSample<M>> out;
  for (const auto& item : py::reinterpret_borrow<py::sequence>(samples)) {
    const std::string name = "samples[" + std::to_string(out.size()) + "]";
    if (!py::isinstance<py::sequence>(item) || py::len(item) != 3) {
      throw_invalid(where, name, repr_of(item), "is not a triple (t, q, v)");
    }
    const py::sequence triple = py::reinterpret_borrow<py::sequence>(item);
    out.push_back({number_arg<double>(triple[0], where, (name + "[0]").c_str()),
                   point_arg(manifold, triple[1], where, (name + "[1]").c_str()),
                   finite_arg<ComponentsOf<M>>(triple[2], where, (name + "[2]").c_str())});
  }
  return out;
}

/// general::check_lagrangian of the request's Lagrangian (a Lagrangian object, or inertia and
/// potential as solve_general takes them) on `manifold`.
template <class M>
mechanics::CheckReport check_on(const M& manifold, const GeneralRequest& r, const py::object& samples,
                                const mechanics::CheckLagrangianOptions& options, const py::object& q, ChartCallbacks* chart) {
  const auto points = manifold_check_samples(manifold, samples, options, q);
  auto state = std::make_shared<CallbackState>();
  std::optional<PythonManifoldLagrangian<M>> python_object;
  bool python = false;
  const general::ErasedLagrangian<M> lagrangian = request_lagrangian(manifold, r, state, python_object, python);
  const auto run = [&] { return general::check_lagrangian(manifold, lagrangian, points); };
  return run_on_chart(chart, [&] { return run_with_callbacks(python_object ? python_object->state() : *state, run); });
}

}  // namespace cartan::python::general_binding
