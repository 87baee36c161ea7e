// cartan.solve_bvp: the collocation solver (include/cartan/numerics/collocation.hpp) for first-order
// systems written in Python, with scipy.integrate.solve_bvp's argument conventions, and its dense
// output (CubicHermite). As SciPy does, fun and fun_jac are called on whole sweeps of the mesh
// (the solver's batched callbacks): x (m,), y (n, m), p (k,) give f (n, m), df_dy (n, n, m) and
// df_dp (n, k, m); without fun_jac the differences move one component at all points at once
// (n + k calls of fun a Jacobian). Single points (m = 1) keep SciPy's shapes, and results may keep
// a trailing axis of length 1 there. The wrapper python/cartan/_bvp.py documents the Python side.
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "cartan/numerics/collocation.hpp"
#include "cartan/numerics/scipy_refinement.hpp"
#include "cartan/principle/options.hpp"  // timed
#include "python_models.hpp"

namespace cartan::python {

namespace {

using numerics::ConstVectorRef;
using numerics::MatrixRef;
using numerics::VectorRef;

constexpr std::string_view kWhere = "cartan.solve_bvp";

/// Copies a callback's returned array into out ((rows,) for a vector, (rows, cols) for a matrix),
/// also accepting SciPy's trailing axis of length 1 ((rows, 1), (rows, cols, 1)).
template <class Out>
void read_result(const py::handle& value, const std::string& who, Out&& out) {
  constexpr bool vector = std::remove_cvref_t<Out>::ColsAtCompileTime == 1;
  const Array a = as_array(value, who, "return value");
  const Eigen::Index rows = out.rows(), cols = out.cols();
  const py::ssize_t ndim = vector ? 1 : 2;
  const bool fits = (a.ndim() == ndim || (a.ndim() == ndim + 1 && a.shape(ndim) == 1)) && a.shape(0) == rows &&
                    (vector || a.shape(1) == cols);
  if (!fits) {
    throw_invalid(who, "return value", "array of shape " + shape_text(a),
                  "must have shape " + shape_text(rows, cols, vector) + " (or with a trailing axis of length 1)");
  }
  const double* data = a.data();
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j) out(i, j) = data[i * cols + j];
  }
}

/// Copies a batched Jacobian (rows, cols, m), SciPy's layout, into out (rows x cols m): column
/// cols j + c of out is [:, c, j].
void read_batched_jacobian(const py::handle& value, const std::string& who, Eigen::Index cols, numerics::MatrixRef out) {
  const Array a = as_array(value, who, "return value");
  const Eigen::Index rows = out.rows(), m = cols > 0 ? out.cols() / cols : 0;
  if (a.ndim() != 3 || a.shape(0) != rows || a.shape(1) != cols || a.shape(2) != m) {
    throw_invalid(who, "return value", "array of shape " + shape_text(a),
                  "must have shape (" + std::to_string(rows) + ", " + std::to_string(cols) + ", " +
                      std::to_string(m) + ")");
  }
  const double* data = a.data();
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (Eigen::Index c = 0; c < cols; ++c) {
      for (Eigen::Index j = 0; j < m; ++j) out(r, cols * j + c) = data[(r * cols + c) * m + j];
    }
  }
}

/// The items of a callback's returned tuple (fun_jac, bc_jac), or throws if there are not `count`.
py::sequence returned_items(const py::object& value, const std::string& who, std::size_t count) {
  if (!py::isinstance<py::sequence>(value) || py::len(value) != count) {
    const std::string type = py::str(py::type::handle_of(value).attr("__name__"));
    const bool sized = py::isinstance<py::sequence>(value);
    throw_invalid(who, "return value", sized ? type + " of length " + std::to_string(py::len(value)) : type,
                  "must be a sequence of " + std::to_string(count) + " arrays");
  }
  return value.cast<py::sequence>();
}

/// The user's functions. With parameters (k > 0) they get p as a last argument, as in SciPy.
struct PythonBvp {
  py::object fun, bc, fun_jac, bc_jac;
  int n = 0, k = 0;
  CallbackState state;

  py::tuple point_args(double t, numerics::ConstVectorRef y, numerics::ConstVectorRef p) const {
    py::array_t<double> x(1);
    x.mutable_at(0) = t;
    const py::array_t<double> column = to_numpy(Eigen::MatrixXd(y));  // (n, 1)
    return k > 0 ? py::make_tuple(x, column, to_numpy(p)) : py::make_tuple(x, column);
  }
  py::tuple batch_args(numerics::ConstVectorRef t, numerics::ConstMatrixRef y, numerics::ConstVectorRef p) const {
    const py::array_t<double> x = to_numpy(Eigen::VectorXd(t));
    const py::array_t<double> columns = to_numpy(Eigen::MatrixXd(y));  // (n, m)
    return k > 0 ? py::make_tuple(x, columns, to_numpy(p)) : py::make_tuple(x, columns);
  }
  py::tuple boundary_args(numerics::ConstVectorRef ya, numerics::ConstVectorRef yb, numerics::ConstVectorRef p) const {
    return k > 0 ? py::make_tuple(to_numpy(ya), to_numpy(yb), to_numpy(p)) : py::make_tuple(to_numpy(ya), to_numpy(yb));
  }

  /// Calls f(*args) under the callback guard and hands the result to read(value, who).
  template <class Read>
  void call(const py::object& f, const char* name, const py::tuple& args, Read&& read) {
    const std::string who = std::string(kWhere) + ": " + name;
    guarded_callback(state, who, [&] {
      read(f(*args), who);
      return 0;
    });
  }
};

numerics::BvpSystem python_system(const std::shared_ptr<PythonBvp>& f) {
  numerics::BvpSystem s;
  s.n = f->n;
  s.k = f->k;
  s.rhs = [f](double t, numerics::ConstVectorRef y, numerics::ConstVectorRef p, numerics::VectorRef dydt) {
    f->call(f->fun, "fun", f->point_args(t, y, p), [&](const py::object& v, const std::string& who) {
      read_result(v, who, dydt);
    });
  };
  s.rhs_batch = [f](numerics::ConstVectorRef t, numerics::ConstMatrixRef y, numerics::ConstVectorRef p,
                    numerics::MatrixRef dydt) {
    f->call(f->fun, "fun", f->batch_args(t, y, p), [&](const py::object& v, const std::string& who) {
      read_result(v, who, dydt);
    });
  };
  s.bc = [f](numerics::ConstVectorRef ya, numerics::ConstVectorRef yb, numerics::ConstVectorRef p, numerics::VectorRef residual) {
    f->call(f->bc, "bc", f->boundary_args(ya, yb, p), [&](const py::object& v, const std::string& who) {
      read_result(v, who, residual);
    });
  };
  // SciPy's fun_jac returns df_dy, or (df_dy, df_dp) with parameters; bc_jac returns
  // (dbc_dya, dbc_dyb), or (dbc_dya, dbc_dyb, dbc_dp).
  if (!f->fun_jac.is_none()) {
    s.rhs_jacobian = [f](double t, numerics::ConstVectorRef y, numerics::ConstVectorRef p, numerics::MatrixRef dfdy, numerics::MatrixRef dfdp) {
      f->call(f->fun_jac, "fun_jac", f->point_args(t, y, p), [&](const py::object& v, const std::string& who) {
        if (f->k == 0) return read_result(v, who, dfdy);
        const py::sequence items = returned_items(v, who, 2);
        read_result(items[0], who + " (df_dy)", dfdy);
        read_result(items[1], who + " (df_dp)", dfdp);
      });
    };
  }
  if (!f->fun_jac.is_none()) {
    s.rhs_jacobian_batch = [f](numerics::ConstVectorRef t, numerics::ConstMatrixRef y, numerics::ConstVectorRef p,
                               numerics::MatrixRef dfdy, numerics::MatrixRef dfdp) {
      f->call(f->fun_jac, "fun_jac", f->batch_args(t, y, p), [&](const py::object& v, const std::string& who) {
        if (f->k == 0) return read_batched_jacobian(v, who, f->n, dfdy);
        const py::sequence items = returned_items(v, who, 2);
        read_batched_jacobian(items[0], who + " (df_dy)", f->n, dfdy);
        read_batched_jacobian(items[1], who + " (df_dp)", f->k, dfdp);
      });
    };
  }
  if (!f->bc_jac.is_none()) {
    s.bc_jacobian = [f](numerics::ConstVectorRef ya, numerics::ConstVectorRef yb, numerics::ConstVectorRef p, numerics::MatrixRef dya, numerics::MatrixRef dyb,
                        numerics::MatrixRef dp) {
      f->call(f->bc_jac, "bc_jac", f->boundary_args(ya, yb, p), [&](const py::object& v, const std::string& who) {
        const py::sequence items = returned_items(v, who, f->k == 0 ? 2 : 3);
        read_result(items[0], who + " (dbc_dya)", dya);
        read_result(items[1], who + " (dbc_dyb)", dyb);
        if (f->k > 0) read_result(items[2], who + " (dbc_dp)", dp);
      });
    };
  }
  return s;
}

numerics::LinearSolverKind parse_linear_solver(const std::string& name) {
  if (name == "block-lu") return numerics::LinearSolverKind::BlockLU;
  if (name == "sparse-lu") return numerics::LinearSolverKind::SparseLU;
  throw_invalid(kWhere, "linear_solver", "\"" + name + "\"", "is not one of: block-lu, sparse-lu");
}

/// SciPy's status codes: 0 success, 1 max_nodes exceeded, 2 singular Jacobian, 3 otherwise
/// (SciPy: bc_tol not met; cartan: Newton or refinement did not converge, or f/bc not finite).
int scipy_status(Status status) {
  switch (status) {
    case Status::Converged: return 0;
    case Status::MaxNodesExceeded: return 1;
    case Status::SingularJacobian: return 2;
    default: return 3;
  }
}

py::dict result_dict(const numerics::BvpResult& r, double seconds) {
  py::dict d;
  d["status"] = scipy_status(r.status);
  d["status_name"] = std::string(to_string(r.status));
  d["message"] = r.message;
  d["success"] = r.success();
  d["x"] = to_numpy(r.t);
  d["y"] = to_numpy(r.y);
  d["yp"] = to_numpy(r.yp);
  d["p"] = r.p.size() > 0 ? py::object(to_numpy(r.p)) : py::object(py::none());
  d["sol"] = r.interpolant();
  d["rms_residuals"] = to_numpy(r.rms_residual);
  d["niter"] = r.refinements + 1;
  d["max_rms_residual"] = r.max_rms_residual;
  d["max_bc_residual"] = r.max_bc_residual;
  d["newton_iterations"] = r.newton_iterations;
  d["jacobian_evaluations"] = r.jacobian_evaluations;
  d["rhs_evaluations"] = r.rhs_evaluations;
  d["solve_time"] = seconds;
  return d;
}

/// S(x) (nu = 0) or S'(x) (nu = 1): (n,) for a scalar x, (n, q) for q times.
py::array_t<double> evaluate_interpolant(const numerics::CubicHermite& s, const py::object& x, int nu) {
  if (nu != 0 && nu != 1) throw_invalid("cartan.BvpSolution", "nu", std::to_string(nu), "must be 0 or 1");
  const Array times = as_array(x, "cartan.BvpSolution", "x");
  if (times.ndim() > 1) {
    throw_invalid("cartan.BvpSolution", "x", "array of shape " + shape_text(times), "must be a number or 1-D");
  }
  const Eigen::Index n = s.value(s.nodes()[0]).size();
  const Eigen::Index q = times.ndim() == 0 ? 1 : times.shape(0);
  Eigen::MatrixXd out(n, q);
  Eigen::VectorXd column(n);
  for (Eigen::Index j = 0; j < q; ++j) {
    s.evaluate(times.data()[j], nu == 0 ? &column : nullptr, nu == 1 ? &column : nullptr);
    out.col(j) = column;
  }
  return times.ndim() == 0 ? to_numpy(Eigen::VectorXd(out.col(0))) : to_numpy(out);
}

}  // namespace

void bind_bvp(py::module_& m) {
  py::class_<numerics::CubicHermite>(m, "BvpSolution",
                                "The C^1 piecewise-cubic dense output of cartan.solve_bvp: sol(x) is y(x), "
                                "sol(x, 1) is y'(x); (n,) for a number x, (n, q) for q times.")
      .def("__call__", &evaluate_interpolant, py::arg("x"), py::arg("nu") = 0)
      .def_property_readonly("x", [](const numerics::CubicHermite& s) { return to_numpy(s.nodes()); }, "The mesh.");

  m.def("_solve_bvp", [](const py::object& fun, const py::object& bc, const py::object& x, const py::object& y,
                         const py::object& p, const py::object& fun_jac, const py::object& bc_jac, double tol,
                         int max_nodes, std::optional<double> bc_tol, int max_newton_iterations, int max_refinements,
                         double fd_step, const std::string& linear_solver) {
    const Eigen::VectorXd mesh = dynamic_matrix(x, kWhere, "x", 1);
    const Eigen::MatrixXd guess = dynamic_matrix(y, kWhere, "y", 2);
    const Eigen::VectorXd parameters = p.is_none() ? Eigen::VectorXd(0) : Eigen::VectorXd(dynamic_matrix(p, kWhere, "p", 1));
    if (bc_tol && !(*bc_tol > 0)) throw_invalid(kWhere, "bc_tol", format_value(*bc_tol), "must be positive");
    const numerics::CollocationOptions options{.tol = tol, .bc_tol = bc_tol.value_or(0), .max_nodes = max_nodes,
                                          .max_newton_iterations = max_newton_iterations,
                                          .max_refinements = max_refinements, .fd_step = fd_step,
                                          .linear_solver = parse_linear_solver(linear_solver)};
    const auto callbacks = std::make_shared<PythonBvp>();
    callbacks->fun = fun;
    callbacks->bc = bc;
    callbacks->fun_jac = fun_jac;
    callbacks->bc_jac = bc_jac;
    callbacks->n = static_cast<int>(guess.rows());
    callbacks->k = static_cast<int>(parameters.size());
    double seconds = 0;
    const numerics::BvpResult r = run_with_callbacks(callbacks->state, [&] {
      return cartan::timed(seconds, [&] { return numerics::solve_collocation(python_system(callbacks), mesh, guess, parameters, options); });
    });
    return result_dict(r, seconds);
  }, py::arg("fun"), py::arg("bc"), py::arg("x"), py::arg("y"), py::arg("p"), py::arg("fun_jac"), py::arg("bc_jac"),
     py::arg("tol"), py::arg("max_nodes"), py::arg("bc_tol"), py::arg("max_newton_iterations"),
     py::arg("max_refinements"), py::arg("fd_step"), py::arg("linear_solver"));

  // SciPy's refinement rule (numerics/scipy_refinement.hpp): the next mesh, the interpolant there
  // and the number of nodes added, from the solution (x, y, yp) and its interval residuals.
  m.def("_scipy_refinement", [](const py::object& x, const py::object& y, const py::object& yp, const py::object& rms,
                                double tol) {
    const numerics::RefinedMesh r = numerics::scipy_refinement(
        numerics::CubicHermite(dynamic_matrix(x, kWhere, "x", 1), dynamic_matrix(y, kWhere, "y", 2), dynamic_matrix(yp, kWhere, "yp", 2)),
        dynamic_matrix(rms, kWhere, "rms", 1), tol);
    return py::make_tuple(to_numpy(r.t), to_numpy(r.y), r.added);
  }, py::arg("x"), py::arg("y"), py::arg("yp"), py::arg("rms"), py::arg("tol"));
}

}  // namespace cartan::python
