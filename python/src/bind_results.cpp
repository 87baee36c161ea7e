// The result file in Python: Result.to_json and cartan.load call the library's one writer and
// reader (cartan/api/result_file.hpp, the CLI's), through a dict of plain fields
// (python/cartan/_results.py shapes them into a Result); the catalogue of spaces (api/spaces.hpp)
// as cartan.SPACES.
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include <nlohmann/json.hpp>

#include "cartan/api/json_io.hpp"
#include "cartan/api/result_file.hpp"
#include "cartan/api/spaces.hpp"
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

/// The problem of a Result's fields (_results.to_json builds the dict): kind "group" (the group's
/// CLI name, the model, the inertia's n or n^2 numbers, lambda, g0, gT) or "manifold" (a space of
/// api/spaces.hpp, model, mass, gravity, the connection and its data, q0, qT, frame0's rows).
std::variant<api::GroupProblem, api::ManifoldProblem> problem_of(const py::dict& d) {
  const auto text = [&](const char* key) { return d[key].cast<std::string>(); };
  const auto number = [&](const char* key) { return d[key].cast<double>(); };
  if (text("kind") == "group") {
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
    return p;
  }
  api::ManifoldProblem p;
  p.manifold = text("manifold");
  p.model = text("model");
  p.mass = to_numbers(d["mass"], "mass");
  p.gravity = number("gravity");
  if (!d["connection"].is_none()) p.connection = parse_enum<connections::ConnectionKind>(text("connection"), kWriteWhere);
  p.lambda = number("lambda");
  p.metric = to_numbers(d["metric"], "metric");
  p.alpha = to_numbers(d["alpha"], "alpha");
  p.q0 = to_numbers(d["q0"], "q0");
  p.qT = to_numbers(d["qT"], "qT");
  p.frame0 = to_numbers(d["frame0"], "frame0");
  p.T = number("T");
  p.N = d["N"].cast<int>();
  return p;
}

/// The record of a Result's fields: its problem (problem_of), the diagnostics, the samples (points
/// and aux as rows: g or q, xi or Xi).
api::ResultRecord record_of(const py::dict& d) {
  const auto text = [&](const char* key) { return d[key].cast<std::string>(); };
  const auto number = [&](const char* key) { return d[key].cast<double>(); };
  api::ResultRecord record;
  record.problem = problem_of(d);
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
  r.samples.points = to_matrix(d["points"], "points");
  r.samples.v = to_matrix(d["v"], "v");
  r.samples.mu = to_matrix(d["mu"], "mu");
  r.samples.aux = to_matrix(d["aux"], "aux");
  const auto* group = std::get_if<api::GroupProblem>(&record.problem);
  r.lie_kernel = group != nullptr && api::lie_kernel(*group);
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
    d["metric"] = p->metric;
    d["alpha"] = p->alpha;
  } else {
    const auto& m = std::get<api::ManifoldProblem>(record.problem);
    d["kind"] = "manifold";
    d["manifold"] = m.manifold;
    d["model"] = m.model;
    d["mass"] = m.mass;
    d["gravity"] = m.gravity;
    d["connection"] = m.connection ? py::object(py::str(std::string(to_string(*m.connection)))) : py::object(py::none());
    d["lambda"] = m.lambda;
    d["metric"] = m.metric;
    d["alpha"] = m.alpha;
    d["q0"] = m.q0;
    d["qT"] = m.qT;
    d["frame0"] = m.frame0;
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
  m.def("_read_result", [](const std::string& text, const std::string& where) {
    return fields_of(api::read_result(io::parse_json(text, where), where));
  }, py::arg("text"), py::arg("where"),
        "The fields of a result file's text: the library's reader, the CLI's (every key checked; ValueError naming "
        "it).");
  m.attr("spaces") = [] {
    py::list out;
    for (const api::SpaceInfo& s : api::spaces()) {
      py::list connections;
      for (const auto c : s.connections) connections.append(std::string(to_string(c)));
      out.append(py::dict(py::arg("name") = std::string(s.name), py::arg("dims") = s.dims,
                          py::arg("point") = std::string(s.point_what), py::arg("connections") = connections,
                          py::arg("gravity") = s.gravity, py::arg("what") = std::string(s.what)));
    }
    return out;
  }();
}

}  // namespace cartan::python
