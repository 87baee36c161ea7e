// The compiled module `cartan._cartan`; the package python/cartan wraps it (STYLE practice 9).
// pybind11 turns std::invalid_argument and std::domain_error into ValueError and other
// std::exceptions into RuntimeError, keeping the message.
#include <algorithm>
#include <atomic>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bind_all.hpp"
#include "cartan/models/catalogue.hpp"
#include "bindings.hpp"
#include "option_words.hpp"

namespace cartan::python {

std::string shape_text(const py::array& a) {
  std::ostringstream out;
  out << '(';
  for (py::ssize_t i = 0; i < a.ndim(); ++i) out << (i ? ", " : "") << a.shape(i);
  out << (a.ndim() == 1 ? ",)" : ")");
  return out.str();
}

std::string repr_of(const py::handle& x) {
  constexpr std::size_t kMaxShown = 60;
  const std::string ascii = py::str(py::module_::import("builtins").attr("ascii")(x)).cast<std::string>();
  std::string text;  // one line: a run of white space (an array's rows) as one space
  for (const char c : ascii) {
    const bool space = c == ' ' || c == '\n' || c == '\t' || c == '\r';
    if (!space || (!text.empty() && text.back() != ' ')) text += space ? ' ' : c;
  }
  if (text.size() > kMaxShown) text = text.substr(0, kMaxShown) + "...";
  return text;
}

std::string shape_text(Eigen::Index rows, Eigen::Index cols, bool vector) {
  return vector ? "(" + std::to_string(rows) + ",)" : "(" + std::to_string(rows) + ", " + std::to_string(cols) + ")";
}

Array as_array(const py::handle& obj, std::string_view where, std::string_view name) {
  Array a = Array::ensure(obj);
  if (!a) {
    PyErr_Clear();
    throw_invalid(where, name, py::repr(obj).cast<std::string>(), "is not an array of numbers");
  }
  return a;
}

Eigen::MatrixXd dynamic_matrix(const py::handle& obj, std::string_view where, std::string_view name, py::ssize_t ndim) {
  const Array a = as_array(obj, where, name);
  if (a.ndim() != ndim) {
    throw_invalid(where, name, "array of shape " + shape_text(a), "must be " + std::to_string(ndim) + "-D");
  }
  const Eigen::Index rows = a.shape(0), cols = ndim == 2 ? a.shape(1) : 1;
  Eigen::MatrixXd out(rows, cols);
  const double* data = a.data();
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j) out(i, j) = data[i * cols + j];
  }
  return out;
}

Array batch_rows(const py::handle& result, std::size_t count, const std::vector<py::ssize_t>& row_shape,
                 std::string_view who) {
  const Array a = as_array(result, who, "return value");
  bool fits = a.ndim() == static_cast<py::ssize_t>(row_shape.size() + 1) && a.shape(0) == static_cast<py::ssize_t>(count);
  for (std::size_t i = 0; fits && i < row_shape.size(); ++i) fits = a.shape(static_cast<py::ssize_t>(i + 1)) == row_shape[i];
  if (!fits) {
    std::string expected = "(" + std::to_string(count);
    for (const py::ssize_t n : row_shape) expected += ", " + std::to_string(n);
    expected += row_shape.empty() ? ",)" : ")";
    throw_invalid(who, "return value", "array of shape " + shape_text(a),
                  "must have shape " + expected + ", one row per point (the model is vectorized)");
  }
  return a;
}

void rethrow_callback_error(const CallbackState& state) {
  if (state.first_error) std::rethrow_exception(state.first_error);
}

PythonModel::PythonModel(const py::object& object, std::string_view kind, std::initializer_list<const char*> required,
                         std::initializer_list<const char*> optional)
    : object_(object), kind_(kind) {
  std::string needs;
  for (const char* m : required) needs += (needs.empty() ? "" : ", ") + std::string(m);
  for (const char* method : required) {
    if (!py::hasattr(object, method)) {
      throw_invalid(kind_, "object", py::repr(object).cast<std::string>(),
                    std::string("has no method ") + method + " (a " + kind_ + " needs " + needs + ")");
    }
    names_.emplace_back(method);
    methods_.push_back(object.attr(method));
  }
  for (const char* method : optional) {
    names_.emplace_back(method);
    methods_.push_back(py::hasattr(object, method) ? py::object(object.attr(method)) : py::object(py::none()));
  }
  vectorized_ = py::hasattr(object, "vectorized") && py::bool_(object.attr("vectorized"));
}

groups::Side parse_side(const std::string& side, std::string_view where) {
  if (side == "left") return groups::Side::Left;
  if (side == "right") return groups::Side::Right;
  throw_invalid(where, "side", "\"" + side + "\"", "is not one of: left, right");
}

transport::TransportMethod parse_transport_method(const std::string& method, std::string_view where) {
  if (method == "lie-euler") return transport::TransportMethod::LieEuler;
  if (method == "magnus2") return transport::TransportMethod::Magnus2;
  if (method == "magnus4") return transport::TransportMethod::Magnus4;
  throw_invalid(where, "method", "\"" + method + "\"", "is not one of: lie-euler, magnus2, magnus4");
}

namespace {

/// The cancel flags of the cancel scopes open on this thread, innermost last: cartan.sweep on
/// local threads runs each task inside one and raises the flag when it is interrupted, so that
/// the solves still running stop at their next iteration (the worker threads see no signal).
thread_local std::vector<std::shared_ptr<std::atomic<bool>>> cancel_scopes;

/// `cartan._cartan._CancelToken`: `with token:` around solves, `token.cancel()` from any thread.
struct CancelToken {
  std::shared_ptr<std::atomic<bool>> flag = std::make_shared<std::atomic<bool>>(false);
};

}  // namespace

SolveMonitor python_monitor(const py::object& progress) {
  const std::shared_ptr<std::atomic<bool>> cancel = cancel_scopes.empty() ? nullptr : cancel_scopes.back();
  SolveMonitor::ProgressCallback report;
  if (!progress.is_none()) {
    // The solver copies and destroys its monitor (stages) without the GIL: it holds the callable
    // through a shared_ptr, whose count is atomic, and only the last owner touches the Python
    // reference count, with the GIL.
    const std::shared_ptr<py::object> callable(new py::object(progress), [](py::object* object) {
      py::gil_scoped_acquire gil;
      delete object;
    });
    report = [callable](const Progress& p) {
      py::gil_scoped_acquire gil;
      (*callable)(std::string(p.stage), p.iteration, p.residual);
    };
  }
  const SolveMonitor monitor(report, [] {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    return false;
  });
  return cancel ? monitor.with_cancel_flag(cancel) : monitor;
}

}  // namespace cartan::python

PYBIND11_MODULE(_cartan, m) {
  m.doc() = "cartan: geometric mechanics on Lie groups with invariant connections (compiled core).";
  m.attr("__version__") = CARTAN_VERSION;
  pybind11::class_<cartan::OptionWords> request_class(m, "_SolveRequest");
  cartan::python::def_option_words(request_class).def(pybind11::init<>());
  m.attr("statuses") = cartan::enum_words<cartan::Status>();
  // The library's defaults (principle/vocabulary.hpp), which cartan.solve and solve_general take.
  m.attr("defaults") = pybind11::dict(pybind11::arg("tol") = cartan::kDefaultTol,
                                      pybind11::arg("max_iterations") = cartan::kDefaultMaxIterations);
  // The library's catalogue of built-in models (models/catalogue.hpp): what result files and the
  // CLI call them, and which class each is (cartan._results.BUILTIN_MODELS).
  pybind11::list models;
  for (const auto& info : cartan::models::model_infos()) {
    models.append(pybind11::dict(pybind11::arg("group") = std::string(info.group),
                                 pybind11::arg("model") = std::string(info.model),
                                 pybind11::arg("type") = std::string(info.type_name),
                                 pybind11::arg("default_inertia") = info.default_inertia));
  }
  m.attr("models") = models;
  using cartan::python::CancelToken;
  pybind11::class_<CancelToken>(m, "_CancelToken",
                                "Solves started inside `with token:` on this thread stop (status interrupted) at "
                                "their next iteration once token.cancel() is called, from any thread.")
      .def(pybind11::init<>())
      .def("cancel", [](CancelToken& t) { t.flag->store(true); })
      .def_property_readonly("cancelled", [](const CancelToken& t) { return t.flag->load(); })
      .def("__enter__", [](CancelToken& t) { cartan::python::cancel_scopes.push_back(t.flag); })
      .def("__exit__", [](CancelToken&, const pybind11::args&) { cartan::python::cancel_scopes.pop_back(); });
  m.def("_check_report", [](const std::string& title, const pybind11::list& checks, int samples) {
    return cartan::python::check_report_dict(cartan::python::check_report_of(title, checks, samples));
  }, pybind11::arg("title"), pybind11::arg("checks"), pybind11::arg("samples"),
     "A CheckReport's dict from the dicts of its checks (cartan.testing), printed by the C++ CheckReport::text.");
  cartan::python::bind_so3(m);
  cartan::python::bind_heisenberg(m);
  cartan::python::bind_se3(m);
  cartan::python::bind_se2(m);
  cartan::python::bind_bvp(m);
  cartan::python::bind_manifolds(m);
  cartan::python::bind_group_manifold(m);
  cartan::python::bind_general(m);
  cartan::python::bind_results(m);
}
