// The compiled module `cartan._cartan`; the package python/cartan wraps it (STYLE practice 9).
// pybind11 turns std::invalid_argument and std::domain_error into ValueError and other
// std::exceptions into RuntimeError, keeping the message.
#include <algorithm>
#include <sstream>

#include "bind_all.hpp"
#include "bindings.hpp"

namespace cartan::python {

std::string shape_text(const py::array& a) {
  std::ostringstream out;
  out << '(';
  for (py::ssize_t i = 0; i < a.ndim(); ++i) out << (i ? ", " : "") << a.shape(i);
  out << (a.ndim() == 1 ? ",)" : ")");
  return out.str();
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
}

Side parse_side(const std::string& side, std::string_view where) {
  if (side == "left") return Side::Left;
  if (side == "right") return Side::Right;
  throw_invalid(where, "side", "\"" + side + "\"", "is not one of: left, right");
}

TransportMethod parse_transport_method(const std::string& method, std::string_view where) {
  if (method == "lie-euler") return TransportMethod::LieEuler;
  if (method == "magnus2") return TransportMethod::Magnus2;
  if (method == "magnus4") return TransportMethod::Magnus4;
  throw_invalid(where, "method", "\"" + method + "\"", "is not one of: lie-euler, magnus2, magnus4");
}

void check_request(const SolveRequest& request, const std::vector<std::string>& names, unsigned accepts) {
  constexpr std::string_view where = "cartan.solve";
  if (std::find(names.begin(), names.end(), request.method) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw_invalid(where, "method", "\"" + request.method + "\"", "is not one of: " + list);
  }
  if (request.order != 1 && request.order != 2) {
    throw_invalid(where, "order", std::to_string(request.order), "must be 1 or 2");
  }
  const auto refuse = [&](bool given, unsigned flag, std::string_view name, const std::string& value) {
    if (given && (accepts & flag) == 0) {
      throw_invalid(where, name, value, "is not an option of method \"" + request.method + "\"");
    }
  };
  refuse(request.has_v0, kV0, "v0", "(given)");
  refuse(request.has_xi0, kXi0, "xi0", "(given)");
  refuse(request.segments.has_value(), kSegments, "segments", std::to_string(request.segments.value_or(0)));
  refuse(request.lambda_start.has_value(), kLambdaStart, "lambda_start", format_value(request.lambda_start.value_or(0)));
  refuse(request.samples.has_value(), kSamples, "samples", std::to_string(request.samples.value_or(0)));
  refuse(request.max_nodes.has_value(), kMaxNodes, "max_nodes", std::to_string(request.max_nodes.value_or(0)));
}

}  // namespace cartan::python

PYBIND11_MODULE(_cartan, m) {
  m.doc() = "cartan: geometric mechanics on Lie groups with invariant connections (compiled core).";
  cartan::python::bind_so3(m);
  cartan::python::bind_heisenberg(m);
  cartan::python::bind_se3(m);
  cartan::python::bind_se2(m);
  cartan::python::bind_bvp(m);
}
