// The result file in Python: SolveResult.to_json and cartan.load call the library's one writer
// and reader (cartan/api/result_file.hpp, the CLI's), through a dict of plain fields
// (python/cartan/_results.py shapes them into a SolveResult).
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include <nlohmann/json.hpp>

#include "cartan/api/json_io.hpp"
#include "cartan/api/result_file.hpp"
#include "cartan/enum_names.hpp"
#include "convert.hpp"
#include "report_dict.hpp"

namespace cartan::python {

namespace {

constexpr std::string_view kWriteWhere = "SolveResult.to_json";

/// Rows (one per time) as a matrix.
Eigen::MatrixXd to_matrix(const py::handle& obj, std::string_view name) { return dynamic_matrix(obj, kWriteWhere, name, 2); }

std::vector<double> to_numbers(const py::handle& obj, std::string_view name) {
  const Array a = as_array(obj, kWriteWhere, name);
  return {a.data(), a.data() + a.size()};
}

/// The record of a SolveResult's fields (_results.to_json builds the dict: the group's CLI name,
/// the inertia's n or n^2 numbers, elements and rows as numbers).
api::ResultRecord record_of(const py::dict& d) {
  const auto text = [&](const char* key) { return d[key].cast<std::string>(); };
  const auto number = [&](const char* key) { return d[key].cast<double>(); };
  api::GroupProblem p;
  p.group = text("group");
  p.model = text("model");
  p.inertia = to_numbers(d["inertia"], "inertia");
  p.connection = parse_enum<connections::ConnectionKind>(text("connection"), kWriteWhere);
  p.lambda = number("lambda");
  p.T = number("T");
  p.N = d["N"].cast<int>();
  p.g0 = to_numbers(d["g0"], "g0");
  p.gT = to_numbers(d["gT"], "gT");
  api::ResultRecord record;
  record.problem = p;
  record.tol = number("tol");
  api::Result& r = record.result;
  r.status = parse_enum<Status>(text("status"), kWriteWhere);
  r.message = text("message");
  r.method = parse_enum<cartan::Method>(text("method"), kWriteWhere);
  r.order = d["order"].cast<int>();
  r.branch = text("branch");
  r.terminal_error = number("terminal_error");
  r.xi_terminal = number("xi_terminal");
  r.outer_iterations = d["outer_iterations"].cast<int>();
  r.inner_iterations = d["inner_iterations"].cast<int>();
  r.sweeps = d["sweeps"].cast<int>();
  r.action = number("action");
  r.solve_time_s = number("solve_time");
  if (!d["mesh_size"].is_none()) {
    r.collocation = CollocationReport{d["mesh_size"].cast<int>(), number("max_residual"), number("group_defect")};
  }
  const Array t = as_array(d["t"], kWriteWhere, "t");
  r.samples.t = Eigen::Map<const Eigen::VectorXd>(t.data(), t.size());
  r.samples.points = to_matrix(d["g"], "g");
  r.samples.v = to_matrix(d["v"], "v");
  r.samples.mu = to_matrix(d["mu"], "mu");
  r.samples.aux = to_matrix(d["xi"], "xi");
  r.lie_kernel = api::lie_kernel(p);
  return record;
}

/// The fields of a record as plain Python values: the problem's (kind "group" or "manifold"),
/// the result's (add_core_fields: the names of every result type), and the samples as arrays
/// (points, aux: g or q, xi or Xi).
py::dict fields_of(const api::ResultRecord& record) {
  const api::Result& r = record.result;
  py::dict d;
  if (const auto* p = std::get_if<api::GroupProblem>(&record.problem)) {
    d["kind"] = "group";
    d["group"] = p->group;
    d["model"] = p->model;
    d["inertia"] = p->inertia;
    d["connection"] = std::string(to_string(p->connection));
    d["lambda"] = p->lambda;
    d["g0"] = p->g0;
    d["gT"] = p->gT;
  } else {
    const auto& m = std::get<api::ManifoldProblem>(record.problem);
    d["kind"] = "manifold";
    d["manifold"] = m.manifold;
  }
  std::visit([&](const auto& p) {
    d["T"] = p.T;
    d["N"] = p.N;
  }, record.problem);
  d["tol"] = record.tol;
  add_core_fields(d, r);
  d["outer_iterations"] = r.outer_iterations;
  d["inner_iterations"] = r.inner_iterations;
  d["action"] = r.action;
  d["group_defect"] = r.collocation ? py::object(py::float_(r.collocation->group_defect)) : py::object(py::none());
  d["lie_kernel"] = r.lie_kernel;
  d["t"] = to_numpy(r.samples.t);
  d["points"] = to_numpy(r.samples.points);
  d["v"] = to_numpy(r.samples.v);
  d["mu"] = to_numpy(r.samples.mu);
  d["aux"] = to_numpy(r.samples.aux);
  return d;
}

}  // namespace

void bind_results(py::module_& m) {
  m.def("_result_text", [](const py::dict& fields) { return api::result_text(record_of(fields)); }, py::arg("fields"),
        "The result file's text (one line of JSON) of a SolveResult's fields: the library's writer, the CLI's.");
  m.def("_read_result", [](const std::string& text, const std::string& where, bool lie_kernel_only) {
    const nlohmann::json j = io::parse_json(text, where);
    if (lie_kernel_only && j.is_object()) {  // a SolveResult holds the Lie-group kernel's fields (xi, P, the action)
      if (j.contains("manifold")) {
        throw_invalid(where, "manifold", io::describe(j["manifold"]),
                      "is a solve_general problem; cartan.load reads cartan.solve's results on a group");
      }
      const std::string cartan_schouten(to_string(connections::ConnectionKind::CartanSchouten));
      if (j.contains("connection") && j["connection"] != cartan_schouten) {
        throw_invalid(where, "connection", io::describe(j["connection"]),
                      "is not one of: " + cartan_schouten + " (the general solver's results are not SolveResults)");
      }
    }
    return fields_of(api::read_result(j, where));
  }, py::arg("text"), py::arg("where"), py::arg("lie_kernel_only"),
        "The fields of a result file's text: the library's reader, the CLI's (every key checked; ValueError naming "
        "it). lie_kernel_only: refuse a manifold's or another connection's result first, naming that key.");
}

}  // namespace cartan::python
