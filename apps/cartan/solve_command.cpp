#include "solve_command.hpp"

#include <cmath>

#include "cartan/models/catalogue.hpp"

namespace cartan::cli {

namespace {

constexpr std::string_view kSolveCommandWhere = "cartan solve";

/// Rows of numbers as a JSON array of arrays.
nlohmann::json json_rows(const Eigen::MatrixXd& x) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index k = 0; k < x.rows(); ++k) {
    const Eigen::RowVectorXd row = x.row(k);
    out.push_back(std::vector<double>(row.data(), row.data() + row.size()));
  }
  return out;
}

/// A number for JSON: NaN and infinities (which JSON lacks) become null.
nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

/// alpha_values as the nested array alpha[i][j][k].
nlohmann::json nested_alpha(const std::vector<double>& values, std::size_t n) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) {
    nlohmann::json plane = nlohmann::json::array();
    for (std::size_t j = 0; j < n; ++j) {
      plane.push_back(std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>((i * n + j) * n),
                                          values.begin() + static_cast<std::ptrdiff_t>((i * n + j + 1) * n)));
    }
    out.push_back(plane);
  }
  return out;
}

/// The connection keys of a group result: its name, and the metric (levi-civita) or alpha
/// (coefficients, as the nested array) echoed; Cartan–Schouten's side of the trivialisation of v.
void add_connection(nlohmann::json& out, const ProblemSpec& spec) {
  out["connection"] = spec.connection;
  switch (connection_kind(spec)) {
    case connections::ConnectionKind::CartanSchouten:
      out["side"] = "left";
      break;
    case connections::ConnectionKind::LeviCivita:
      out["metric"] = spec.metric;
      break;
    case connections::ConnectionKind::Coefficients:
      out["alpha"] = nested_alpha(spec.alpha_values,
                                  static_cast<std::size_t>(models::find_model(spec.group, spec.model, kSolveCommandWhere).dim));
      break;
  }
}

}  // namespace

cartan::SolveOptions solve_options(const ProblemSpec& spec) {
  cartan::SolveOptions options;
  options.method = parse_enum<cartan::Method>(spec.method, "cartan solve");
  options.continuation = parse_enum<cartan::Continuation>(spec.continuation, "cartan solve");
  options.order = spec.order == 2 ? cartan::SchemeOrder::Second : cartan::SchemeOrder::First;
  options.tol = spec.tol;
  options.max_iterations = spec.max_iterations;
  if (spec.time_limit > 0) options.time_limit = spec.time_limit;
  if (spec.segments > 0) options.segments = spec.segments;
  options.samples = spec.samples;
  return options;
}

SO3Endpoints so3_endpoints(const ProblemSpec& spec) {
  const models::ModelInfo& model = models::find_model(spec.group, spec.model, kSolveCommandWhere);
  model.check_element(spec.g0, kSolveCommandWhere, "g0");
  if (spec.a0.empty()) model.check_element(spec.gT, kSolveCommandWhere, "gT");
  return {models::element_of<groups::SO3>(spec.g0), models::element_of<groups::SO3>(final_element(spec))};
}

nlohmann::json solve(const ProblemSpec& spec, const SolveMonitor& monitor) {
  cartan::SolveOptions options = solve_options(spec);
  options.monitor = monitor;
  const api::Guess guess{spec.v0, spec.xi0};
  return result_json(spec, is_manifold_problem(spec) ? api::solve(manifold_problem(spec), options, guess, kSolveCommandWhere)
                                                     : api::solve(group_problem(spec), options, guess, kSolveCommandWhere));
}

nlohmann::json result_json(const ProblemSpec& spec, const api::Result& r) {
  nlohmann::json out = result_header(spec, std::string(to_string(r.status)), r.message, std::string(to_string(r.method)),
                                     r.order, r.branch);
  if (r.status == Status::Interrupted) return out;  // never written (exit 130): no trajectory to format
  if (!is_manifold_problem(spec)) add_connection(out, spec);
  const api::Samples& x = r.samples;
  out["t"] = std::vector<double>(x.t.data(), x.t.data() + x.t.size());
  out[is_manifold_problem(spec) ? "q" : "g"] = json_rows(x.points);
  out["v"] = json_rows(x.v);
  out["mu"] = json_rows(x.mu);
  out[r.lie_kernel ? "xi" : "Xi"] = json_rows(x.aux);
  if (r.frame0) out["frame0"] = json_rows(*r.frame0);
  out["terminal_error"] = r.terminal_error;
  out["xi_terminal"] = r.xi_terminal;
  out["iterations"] = {{"outer", r.outer_iterations}, {"inner", r.inner_iterations}, {"sweeps", r.sweeps}};
  if (r.lie_kernel) out["action"] = number_or_null(r.action);  // the general kernel computes none
  out["solve_time_s"] = r.solve_time_s;
  if (r.collocation) {
    out["mesh_size"] = r.collocation->mesh_size;
    out["max_residual"] = r.collocation->max_residual;
    if (std::isfinite(r.collocation->group_defect)) out["group_defect"] = r.collocation->group_defect;
  }
  return out;
}

}  // namespace cartan::cli
