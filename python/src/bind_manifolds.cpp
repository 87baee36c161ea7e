// The manifolds with a linear connection (include/cartan/manifolds) as Python classes, in their
// own translation unit (GroupManifold in bind_group_manifold.cpp); bind_general.cpp solves on them.
//
// Python classes: Sphere, HyperbolicPlane (Quadric<+-1>), Euclidean (R^2 or R^3 with constant
// Christoffel symbols: one class over Euclidean<2> and Euclidean<3>) and Chart (R^2 or R^3 with
// Christoffel symbols from Python callables). Each has the same geometry methods (christoffel,
// torsion, curvature, step, difference, transport_along_step, tangent_basis, ...), bound once by
// def_manifold_methods (general_binding.hpp).

#include <limits>

#include "general_binding.hpp"

namespace cartan::python {

namespace {

using namespace general_binding;
using manifolds::HyperbolicPlane;
using manifolds::Sphere;

template <class Q>
py::class_<Q> bind_quadric(py::module_& m, const char* name, const char* doc) {
  py::class_<Q> cls(m, name, doc);
  cls.def(py::init<>());
  def_manifold_methods(cls, name);
  cls.def("__repr__", [name](const Q&) { return std::string(name) + "()"; });
  // No state: a result's problem travels with it (pickling, processes).
  cls.def(py::pickle([](const Q&) { return py::tuple(); }, [](const py::tuple&) { return Q(); }));
  return cls;
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

/// Whether x is an integer (Python's or NumPy's) and not an array.
bool is_integer(const py::handle& x) {
  return PyIndex_Check(x.ptr()) && !PyBool_Check(x.ptr()) && !py::isinstance<py::array>(x);
}

void bind_euclidean(py::module_& m) {
  py::class_<EuclideanManifold> cls(
      m, "Euclidean", "R^2 or R^3 with a constant linear connection nabla_{e_i} e_j = Gamma^k_ij e_k (any torsion "
                      "and curvature); points and vectors are coordinates.");
  cls.def(py::init([](py::object christoffel, py::object dim) {
            // Euclidean(m): an integer in the symbols' place is the dimension (no symbols are a number)
            if (is_integer(christoffel)) {
              if (!dim.is_none()) {
                throw_invalid("Euclidean", "dim", repr_of(dim),
                              "is given twice (Euclidean(" + repr_of(christoffel) + ") is Euclidean(dim=" +
                                  repr_of(christoffel) + "))");
              }
              std::swap(christoffel, dim);
            }
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
          "dim = m for the flat, torsion-free connection (also Euclidean(m), m an integer).");
  def_manifold_methods(cls, "Euclidean");
  const auto symbols = [](const EuclideanManifold& h) {
    return visit_holder(h, [](const auto& e) {
      constexpr int n = std::decay_t<decltype(e)>::kDim;
      std::array<Square<n>, n> out;  // out[k](i, j) = Gamma^k_ij
      for (int i = 0; i < n; ++i) {
        for (int k = 0; k < n; ++k) out[k].row(i) = e.coefficients()[i].row(k);
      }
      return tensor_numpy<n>(out);
    });
  };
  cls.def_property_readonly("christoffel_symbols", symbols, "The (m, m, m) array christoffel[k, i, j] = Gamma^k_ij.");
  cls.def("__repr__", [](const EuclideanManifold& h) {
    return visit_holder(h, [](const auto& e) { return "Euclidean(dim=" + std::to_string(e.kDim) + ")"; });
  });
  // Its state is its Christoffel symbols: a result's problem travels with it (pickling, processes).
  cls.def(py::pickle(
      [symbols](const EuclideanManifold& h) { return py::make_tuple(symbols(h)); },
      [](const py::tuple& state) {
        const Array a = as_array(state[0], "Euclidean", "christoffel");
        return a.shape(0) == 2 ? make_euclidean<2>(state[0]) : make_euclidean<3>(state[0]);
      }));
}

// ---- Chart ------------------------------------------------------------------------------------

/// NaN in every entry: a field's value outside the chart.
template <class R>
R outside_the_chart() {
  R value;
  if constexpr (requires { value.setConstant(0.0); }) {
    value.setConstant(std::numeric_limits<double>::quiet_NaN());
  } else {
    for (auto& entry : value) entry.setConstant(std::numeric_limits<double>::quiet_NaN());
  }
  return value;
}

/// A Python callable of the point as a field of the chart: the result converted by `convert`.
/// During a solve an Exception the callable raises marks the point outside the chart, as NaN does
/// (documented: ChartCallbacks), and any other error is recorded for the solve (callbacks.state),
/// after which a later call fails at once; outside a solve every exception passes through.
template <int N, class R, class Convert>
auto chart_field(const std::shared_ptr<ChartCallbacks>& callbacks, py::object fn, const char* who, Convert convert) {
  return [callbacks, fn = std::move(fn), who, convert](const Eigen::Matrix<double, N, 1>& q) -> R {
    py::gil_scoped_acquire gil;
    if (callbacks->solving && callbacks->state.first_error) {
      throw ModelError(std::string("Chart.") + who + ": an earlier callback failed");
    }
    py::object value;
    try {
      value = fn(to_numpy(q));
    } catch (py::error_already_set& e) {
      if (!callbacks->solving || !e.matches(PyExc_Exception)) {
        if (callbacks->solving && !callbacks->state.first_error) callbacks->state.first_error = std::current_exception();
        throw;
      }
      if (callbacks->outside.empty()) {
        callbacks->outside = std::string("Chart.") + who + " raised " + py::str(e.type().attr("__name__")).cast<std::string>() +
                             " at q = " + format_value(q) + " (" + py::str(e.value()).cast<std::string>() + ")";
      }
      return outside_the_chart<R>();
    }
    try {
      return convert(value);
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
          "metric the connection preserves; the default frame tangent_basis(q) is then the coordinate basis "
          "orthonormalised in it, so that l = 1/2 |v|^2 is 1/2 g(q', q')). parallel: declare nabla T = nabla R = 0 (e.g. constant curvature), "
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
}

}  // namespace cartan::python
