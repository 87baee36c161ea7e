#include "result_reader.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/status.hpp"
#include "cartan/transported/method.hpp"
#include "json_io.hpp"
#include "cartan/models/catalogue.hpp"

namespace cartan::cli {

namespace {

constexpr std::string_view kResultWhere = "cartan verify";
constexpr std::string_view kResultFile = "a result file";

/// The first and last times must match 0 and T to this fraction of T (shooting accumulates t_k
/// by adding h, which leaves a rounding error of about N eps T).
constexpr double kTimeSpanTolerance = 1e-6;

[[noreturn]] void bad_result(const std::string& name, const std::string& value, const std::string& problem) {
  throw_invalid(kResultWhere, name, value, problem);
}

std::string one_of(const nlohmann::json& value, const std::string& name, const std::vector<std::string>& choices) {
  const std::string s = json_text(value, kResultWhere, name);
  if (std::find(choices.begin(), choices.end(), s) == choices.end()) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    bad_result(name, describe(value), "is not one of: " + list);
  }
  return s;
}

/// A flat list of exactly `size` finite numbers.
Eigen::VectorXd numbers(const nlohmann::json& value, const std::string& name, std::size_t size) {
  if (!value.is_array() || value.size() != size) {
    bad_result(name, describe(value), "must be a list of " + std::to_string(size) + " numbers");
  }
  const std::vector<double> x = json_numbers(value, kResultWhere, name);
  return Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
}

/// `rows` rows of `width` finite numbers each, as a rows x width matrix.
Eigen::MatrixXd table(const nlohmann::json& value, const std::string& name, std::size_t rows, std::size_t width) {
  if (!value.is_array() || value.size() != rows) {
    bad_result(name, describe(value), "must have " + std::to_string(rows) + " rows (one per entry of t)");
  }
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(width));
  for (std::size_t k = 0; k < rows; ++k) {
    out.row(static_cast<Eigen::Index>(k)) = numbers(value[k], name + "[" + std::to_string(k) + "]", width).transpose();
  }
  return out;
}

Eigen::VectorXd times(const nlohmann::json& value, double T) {
  if (!value.is_array() || value.size() < 2) bad_result("t", describe(value), "must be a list of at least 2 times");
  const Eigen::VectorXd t = numbers(value, "t", value.size());
  for (Eigen::Index k = 1; k < t.size(); ++k) {
    if (!(t[k] > t[k - 1])) {
      bad_result("t[" + std::to_string(k) + "]", format_value(t[k]),
          "is not greater than t[" + std::to_string(k - 1) + "] = " + format_value(t[k - 1]) + " (times must increase)");
    }
  }
  if (std::abs(t[0]) > kTimeSpanTolerance * T) bad_result("t[0]", format_value(t[0]), "must be 0");
  if (std::abs(t[t.size() - 1] - T) > kTimeSpanTolerance * T) {
    bad_result("t[" + std::to_string(t.size() - 1) + "]", format_value(t[t.size() - 1]), "must equal T = " + format_value(T));
  }
  return t;
}

/// An n x n x n nested array of finite numbers, flattened in (i, j, k) order.
std::vector<double> nested_numbers(const nlohmann::json& value, const std::string& name, std::size_t n) {
  std::vector<double> out;
  if (!value.is_array() || value.size() != n) bad_result(name, describe(value), "must be an n x n x n array, n = " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::MatrixXd plane = table(value[i], name + "[" + std::to_string(i) + "]", n, n);
    for (Eigen::Index a = 0; a < plane.rows(); ++a) {
      for (Eigen::Index b = 0; b < plane.cols(); ++b) out.push_back(plane(a, b));
    }
  }
  return out;
}

/// A --manifold result (the sphere, the hyperbolic plane): its echoed fields (checked and normalised by validate), then t,
/// q (3 numbers a row), v, mu (2) and Xi (4).
ResultFile read_manifold(const nlohmann::json& j, ResultFile& r) {
  for (const auto& field : problem_fields()) {
    if (!field.echoed || field.scope == ProblemField::Scope::Group) continue;
    read_field(r.problem, field, require_key(j, field.key, kResultWhere, kResultFile), kResultWhere);
  }
  if (!is_result_order(r.order)) {
    bad_result("order", std::to_string(r.order), kResultOrderRule);
  }
  validate(r.problem);
  r.t = times(require_key(j, "t", kResultWhere, kResultFile), r.problem.T);
  const auto rows = static_cast<std::size_t>(r.t.size());
  r.g = table(require_key(j, "q", kResultWhere, kResultFile), "q", rows, 3);
  r.v = table(require_key(j, "v", kResultWhere, kResultFile), "v", rows, 2);
  r.mu = table(require_key(j, "mu", kResultWhere, kResultFile), "mu", rows, 2);
  r.Xi = table(require_key(j, "Xi", kResultWhere, kResultFile), "Xi", rows, 4);
  return r;
}

/// The echoed problem fields (problem_fields()), read and checked as a problem file's, then the
/// model (models/catalogue.hpp), its inertia (by the library's model) and the boundary elements.
ProblemSpec problem_of(const nlohmann::json& j) {
  ProblemSpec p;
  for (const auto& field : problem_fields()) {
    if (!field.echoed || field.scope == ProblemField::Scope::Manifold) continue;
    read_field(p, field, require_key(j, field.key, kResultWhere, kResultFile), kResultWhere);
    if (field.key == "group" || field.key == "model") continue;  // checked against the table below
    check_field(p, field, kResultWhere);
  }
  const models::ModelInfo& model = models::find_model(p.group, p.model, kResultWhere);
  const auto n = static_cast<std::size_t>(model.dim);
  if (j.contains("side") && json_text(j["side"], kResultWhere, "side") != "left") {
    bad_result("side", describe(j["side"]), "must be \"left\" (the transported velocity is left-trivialised)");
  }
  if (j.contains("connection")) {  // cartan-schouten, or the general solver's on a group (api::GroupProblem)
    p.connection = json_text(j["connection"], kResultWhere, "connection");
    if (j.contains("metric")) p.metric = json_numbers(j["metric"], kResultWhere, "metric");
    if (j.contains("alpha")) p.alpha_values = nested_numbers(j["alpha"], "alpha", n);
    check_connection(p, n);
  }
  for (const char* key : {"g0", "gT"}) {
    const Eigen::VectorXd x = numbers(require_key(j, key, kResultWhere, kResultFile), key, model.element_size);
    (key == std::string("g0") ? p.g0 : p.gT) = std::vector<double>(x.data(), x.data() + x.size());
    model.check_element(key == std::string("g0") ? p.g0 : p.gT, kResultWhere, key);
  }
  api::check(group_problem(p), {}, kResultWhere);  // the inertia and the connection's numbers: the library's checks
  return p;
}

ResultFile read(const nlohmann::json& j) {
  if (!j.is_object()) bad_result("result file", describe(j), "must be a JSON object");
  ResultFile r;
  r.status = one_of(require_key(j, "status", kResultWhere, kResultFile), "status", enum_words<Status>());
  const auto read_method_and_order = [&] {
    r.method = one_of(require_key(j, "method", kResultWhere, kResultFile), "method", enum_words<cartan::Method>());
    r.order = json_integer(require_key(j, "order", kResultWhere, kResultFile), kResultWhere, "order");
    if (!is_result_order(r.order)) bad_result("order", std::to_string(r.order), kResultOrderRule);
  };
  if (j.contains("manifold")) {
    read_method_and_order();
    return read_manifold(j, r);
  }
  r.problem = problem_of(j);
  const models::ModelInfo& model = models::find_model(r.problem.group, r.problem.model, kResultWhere);
  read_method_and_order();
  r.t = times(require_key(j, "t", kResultWhere, kResultFile), r.problem.T);
  const auto rows = static_cast<std::size_t>(r.t.size());
  r.g = table(require_key(j, "g", kResultWhere, kResultFile), "g", rows, model.element_size);
  for (Eigen::Index k = 0; k < r.g.rows(); ++k) {
    const Eigen::VectorXd row = r.g.row(k).transpose();
    model.check_element(std::vector<double>(row.data(), row.data() + row.size()), kResultWhere, "g[" + std::to_string(k) + "]");
  }
  const auto n = static_cast<std::size_t>(model.dim);
  r.v = table(require_key(j, "v", kResultWhere, kResultFile), "v", rows, n);
  r.mu = table(require_key(j, "mu", kResultWhere, kResultFile), "mu", rows, n);
  if (r.general()) {
    r.Xi = table(require_key(j, "Xi", kResultWhere, kResultFile), "Xi", rows, n * n);
  } else {
    r.xi = table(require_key(j, "xi", kResultWhere, kResultFile), "xi", rows, n);
  }
  return r;
}

}  // namespace

ResultFile read_result(const nlohmann::json& j) {
  try {
    return read(j);
  } catch (const nlohmann::json::exception& e) {  // unreachable by the checks above; kept as a guarantee
    throw std::invalid_argument(std::string(kResultWhere) + ": result file: " + e.what());
  }
}

}  // namespace cartan::cli
