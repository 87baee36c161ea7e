// The result file's one writer and one reader (cartan/api/result_file.hpp).
#include "cartan/api/result_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "cartan/api/json_io.hpp"
#include "cartan/api/spaces.hpp"
#include "cartan/enum_names.hpp"
#include "cartan/errors.hpp"
#include "cartan/models/catalogue.hpp"
#include "cartan/principle/horizon.hpp"
#include "cartan/scheme_order.hpp"

namespace cartan::api {

namespace {

using nlohmann::json;

/// The first and last times must match 0 and T to this fraction of T (shooting accumulates t_k
/// by adding h, which leaves a rounding error of about N eps T).
constexpr double kTimeSpanTolerance = 1e-6;
constexpr std::string_view kManifoldModel = "particle";
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- Writing ------------------------------------------------------------------------------------

/// A number for JSON: NaN and infinities (which JSON lacks) become null.
json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(); }

/// Numbers as a JSON array (number_or_null each).
template <class Numbers>
json json_list(const Numbers& x) {
  json out = json::array();
  for (const double value : x) out.push_back(number_or_null(value));
  return out;
}

/// Rows of numbers as a JSON array of arrays.
template <class Derived>
json json_rows(const Eigen::DenseBase<Derived>& x) {
  json out = json::array();
  for (Eigen::Index k = 0; k < x.rows(); ++k) out.push_back(json_list(x.row(k)));
  return out;
}

/// `rows` x `width` numbers stored row-major from `values` as rows.
json json_rows(const double* values, std::size_t rows, std::size_t width) {
  return json_rows(Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values, static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(width)));
}

/// The dimension n of a group problem's algebra (a Python model: its group's first model's).
const models::ModelInfo& group_info(const GroupProblem& p, std::string_view where) {
  const bool python_model = p.model.starts_with(kPythonModelPrefix);
  return models::find_model(p.group, python_model ? std::string_view{} : std::string_view(p.model), where);
}

/// alpha's n^3 numbers as n planes of n rows: alpha[i][j][k].
json alpha_planes(const std::vector<double>& alpha, std::size_t n) {
  if (alpha.size() != n * n * n) {
    throw_invalid("cartan::api::result_json", "alpha", excerpt(alpha), "must have n^3 = " + std::to_string(n * n * n) + " numbers");
  }
  json out = json::array();
  for (std::size_t i = 0; i < n; ++i) out.push_back(json_rows(alpha.data() + i * n * n, n, n));
  return out;
}

/// n numbers (a diagonal) as a list, n^2 numbers as n rows.
json matrix_numbers(const std::vector<double>& x, std::size_t n) {
  return x.size() == n * n && n > 1 ? json_rows(x.data(), n, n) : json_list(x);
}

void write_problem(json& out, const GroupProblem& p) {
  const auto n = static_cast<std::size_t>(group_info(p, "cartan::api::result_json").dim);
  out["group"] = p.group;
  out["model"] = p.model;
  out["inertia"] = matrix_numbers(p.inertia, n);
  // λ is a parameter of CS-conn only: null under another connection (as Python's None), not the
  // default the CLI's flag holds
  out["lambda"] = p.connection == connections::ConnectionKind::CartanSchouten ? number_or_null(p.lambda) : json();
  out["g0"] = json_list(p.g0);
  out["gT"] = json_list(p.gT);
  out["connection"] = to_string(p.connection);
  switch (p.connection) {
    case connections::ConnectionKind::CartanSchouten:
      out["side"] = "left";  // v is left-trivialised (eq:reduced-system)
      break;
    case connections::ConnectionKind::LeviCivita:
      out["metric"] = json_list(p.metric);
      break;
    case connections::ConnectionKind::Coefficients:
      out["alpha"] = alpha_planes(p.alpha, n);
      break;
  }
  out["T"] = number_or_null(p.T);
  out["N"] = p.N;
}

/// The widths of a manifold problem's rows: a point's numbers d_q, a tangent vector's d, the
/// dimension m (euclidean: the length of q0, 2 or 3).
struct ManifoldWidths {
  std::size_t point, vector, m;
};

ManifoldWidths manifold_widths(const ManifoldProblem& p, std::string_view where) {
  if (p.manifold.starts_with(kPythonModelPrefix)) {  // a Chart defined in Python: m coordinates
    const std::size_t m = coordinate_count(p.manifold, p.q0, where);
    return {m, m, m};
  }
  const SpaceInfo& space = find_space(p.manifold, where);
  switch (space.kind) {
    case SpaceKind::Group: {
      const models::ModelInfo& info = models::find_model(space.name, {}, where);
      const auto m = static_cast<std::size_t>(info.dim);
      return {info.element_size, m, m};
    }
    case SpaceKind::Quadric: return {3, 3, 2};
    case SpaceKind::Euclidean: {
      const std::size_t m = coordinate_count(p.manifold, p.q0, where);
      return {m, m, m};
    }
  }
  throw std::logic_error("manifold_widths: unknown kind of space");
}

void write_problem(json& out, const ManifoldProblem& p) {
  const ManifoldWidths w = manifold_widths(p, "cartan::api::result_json");
  out["manifold"] = p.manifold;
  out["model"] = p.model;
  out["mass"] = matrix_numbers(p.mass, w.m);
  // null where gravity does not apply (a group, a chart: Python's None), not a G = 0 the space could take
  const bool vertical = !p.manifold.starts_with(kPythonModelPrefix) && find_space(p.manifold, "cartan::api::result_json").gravity;
  out["gravity"] = vertical ? number_or_null(p.gravity) : json();
  if (p.connection) {
    out["connection"] = to_string(*p.connection);
    if (*p.connection == connections::ConnectionKind::CartanSchouten) out["lambda"] = number_or_null(p.lambda);
    if (!p.metric.empty()) out["metric"] = matrix_numbers(p.metric, w.m);
    if (*p.connection == connections::ConnectionKind::Coefficients) out["alpha"] = alpha_planes(p.alpha, w.m);
  }
  out["q0"] = json_list(p.q0);
  out["qT"] = json_list(p.qT);
  if (!p.frame0.empty()) out["frame0"] = json_rows(p.frame0.data(), w.m, w.vector);
  out["T"] = number_or_null(p.T);
  out["N"] = p.N;
}

// ---- Reading ------------------------------------------------------------------------------------

/// Reads one document for `where`: each helper names the key it reads in its messages.
class Reader {
 public:
  Reader(const json& j, std::string_view where) : j_(j), where_(where) {}

  [[noreturn]] void bad(const std::string& name, const std::string& value, const std::string& problem) const {
    throw_invalid(where_, name, value, problem);
  }

  const json& key(const std::string& name) const { return io::require_key(j_, name, where_, "a result file"); }

  std::string text(const std::string& name) const { return io::json_text(key(name), where_, name); }

  /// A word of E; the key is E's name (status, method, connection), which parse_enum's message uses.
  template <NamedEnum E>
  E word(const std::string& name) const {
    return parse_enum<E>(text(name), where_);
  }

  int integer(const json& value, const std::string& name) const { return io::json_integer(value, where_, name); }
  int integer(const std::string& name) const { return integer(key(name), name); }

  /// A finite number.
  double number(const std::string& name) const {
    const double x = io::json_number(key(name), where_, name);
    if (!std::isfinite(x)) bad(name, format_value(x), "is not finite");
    return x;
  }

  /// A number, or null for NaN (JSON lacks NaN and the infinities).
  double number_or_null(const json& value, const std::string& name) const {
    return value.is_null() ? kNaN : io::json_number(value, where_, name);
  }
  double number_or_null(const std::string& name) const { return number_or_null(key(name), name); }

  /// An array of finite numbers (or of rows of them, read row-major), of one of `sizes` when given.
  std::vector<double> numbers(const json& value, const std::string& name, const std::vector<std::size_t>& sizes = {},
                              const std::string& what = "") const {
    if (!value.is_array()) bad(name, io::describe(value), "must be a list of numbers");
    std::vector<double> x = io::json_numbers(value, where_, name);
    if (!sizes.empty() && std::find(sizes.begin(), sizes.end(), x.size()) == sizes.end()) {
      bad(name, excerpt(x), "must have " + what);
    }
    return x;
  }
  /// A flat list of exactly `size` finite numbers.
  std::vector<double> numbers(const std::string& name, std::size_t size) const {
    const json& value = key(name);
    if (!value.is_array() || value.size() != size) {
      bad(name, io::describe(value), "must be a list of " + std::to_string(size) + " numbers");
    }
    return numbers(value, name);
  }

  /// `rows` rows of `width` numbers (null: NaN) as a rows x width matrix.
  Eigen::MatrixXd table(const json& value, const std::string& name, std::size_t rows, std::size_t width) const {
    if (!value.is_array() || value.size() != rows) {
      bad(name, io::describe(value), "must have " + std::to_string(rows) + " rows (one per entry of t)");
    }
    Eigen::MatrixXd out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(width));
    for (std::size_t k = 0; k < rows; ++k) {
      const std::string row = name + "[" + std::to_string(k) + "]";
      if (!value[k].is_array() || value[k].size() != width) {
        bad(row, io::describe(value[k]), "must be a list of " + std::to_string(width) + " numbers");
      }
      for (std::size_t i = 0; i < width; ++i) {
        out(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)) =
            number_or_null(value[k][i], row + "[" + std::to_string(i) + "]");
      }
    }
    return out;
  }
  Eigen::MatrixXd table(const std::string& name, std::size_t rows, std::size_t width) const {
    return table(key(name), name, rows, width);
  }

  const json& document() const { return j_; }
  std::string_view where() const { return where_; }

 private:
  const json& j_;
  std::string_view where_;
};

/// T, N and tol: the horizon and the tolerance of every problem (principle/horizon.hpp).
template <class Problem>
void read_horizon(const Reader& in, Problem& p, double& tol) {
  p.T = in.number("T");
  p.N = in.integer("N");
  require_horizon(p.T, p.N, in.where());
  tol = in.number("tol");
  require_tolerance(tol, in.where());
}

/// alpha[i][j][k]: n planes of n rows of n numbers, as n^3 numbers in (i, j, k) order.
std::vector<double> read_alpha(const Reader& in, std::size_t n) {
  const json& alpha = in.key("alpha");
  if (!alpha.is_array() || alpha.size() != n) {
    in.bad("alpha", io::describe(alpha), "must be an n x n x n array, n = " + std::to_string(n));
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::MatrixXd plane = in.table(alpha[i], "alpha[" + std::to_string(i) + "]", n, n);
    for (Eigen::Index a = 0; a < plane.rows(); ++a) {
      for (Eigen::Index b = 0; b < plane.cols(); ++b) out.push_back(plane(a, b));
    }
  }
  return out;
}

/// A group problem's fields, in the order `cartan verify` has always named them: the names, the
/// numbers, the connection, the boundary elements, then the inertia's size.
GroupProblem read_group_problem(const Reader& in, double& tol) {
  GroupProblem p;
  p.group = in.text("group");
  p.model = in.text("model");
  const bool python_model = p.model.starts_with(kPythonModelPrefix);
  const models::ModelInfo& info = group_info(p, in.where());
  const auto n = static_cast<std::size_t>(info.dim);
  const json& inertia = in.key("inertia");
  const json& lambda = in.key("lambda");
  read_horizon(in, p, tol);
  const json& j = in.document();
  if (j.contains("connection")) p.connection = in.word<connections::ConnectionKind>("connection");
  // a finite λ under CS-conn; under another connection it is no parameter (null, or a number
  // written before 2026-12-08, read and not used)
  p.lambda = p.connection == connections::ConnectionKind::CartanSchouten ? in.number("lambda")
                                                                         : in.number_or_null(lambda, "lambda");
  if (j.contains("side") && in.text("side") != "left") {
    in.bad("side", io::describe(j["side"]), "must be \"left\" (the transported velocity is left-trivialised)");
  }
  if (p.connection == connections::ConnectionKind::LeviCivita && j.contains("metric")) {
    p.metric = in.numbers(j["metric"], "metric", {n, n * n}, std::to_string(n) + " or " + std::to_string(n * n) + " numbers");
  }
  if (p.connection == connections::ConnectionKind::Coefficients) p.alpha = read_alpha(in, n);
  p.g0 = in.numbers("g0", info.element_size);
  p.gT = in.numbers("gT", info.element_size);
  if (!(python_model && inertia.is_array() && inertia.empty())) {  // a Python model may have none
    p.inertia = in.numbers(inertia, "inertia", {n, n * n},
                           std::to_string(n) + " numbers (the diagonal) or " + std::to_string(n * n) + " (the matrix)");
  }
  return p;
}

/// A manifold problem's fields: the names, the points (which give euclidean's dimension), the
/// Lagrangian's numbers, the connection, the frame, the horizon.
ManifoldProblem read_manifold_problem(const Reader& in, double& tol) {
  ManifoldProblem p;
  p.manifold = in.text("manifold");
  if (!p.manifold.starts_with(kPythonModelPrefix)) (void)find_space(p.manifold, in.where());
  p.model = in.text("model");
  if (p.model != kManifoldModel && !p.model.starts_with(kPythonModelPrefix)) {
    in.bad("model", quote_input(p.model), "is not a model of " + p.manifold + " (models: particle, or python:<type name>)");
  }
  p.q0 = in.numbers(in.key("q0"), "q0");
  p.qT = in.numbers(in.key("qT"), "qT");
  const ManifoldWidths w = manifold_widths(p, in.where());
  const std::string sizes = std::to_string(w.m) + " numbers (the diagonal) or " + std::to_string(w.m * w.m) + " (the matrix)";
  p.mass = in.numbers(in.key("mass"), "mass", {w.m, w.m * w.m}, sizes);
  p.gravity = in.key("gravity").is_null() ? 0.0 : in.number("gravity");  // null: gravity does not apply
  const json& j = in.document();
  if (j.contains("connection")) p.connection = in.word<connections::ConnectionKind>("connection");
  if (j.contains("lambda")) p.lambda = in.number("lambda");
  if (j.contains("metric")) p.metric = in.numbers(j["metric"], "metric", {w.m, w.m * w.m}, sizes);
  if (p.connection == connections::ConnectionKind::Coefficients) p.alpha = read_alpha(in, w.m);
  if (j.contains("frame0")) {
    const Eigen::MatrixXd rows = in.table("frame0", w.m, w.vector);
    for (Eigen::Index i = 0; i < rows.rows(); ++i) {
      for (Eigen::Index k = 0; k < rows.cols(); ++k) p.frame0.push_back(rows(i, k));
    }
  }
  read_horizon(in, p, tol);
  return p;
}

/// The widths of a record's rows: the point's numbers, n, and the auxiliary's (xi: n, Xi: n^2).
struct Widths {
  std::size_t point, n, aux;
};

Widths widths(const ResultRecord& r, std::string_view where) {
  if (const auto* p = std::get_if<GroupProblem>(&r.problem)) {
    const models::ModelInfo& info = group_info(*p, where);
    const auto n = static_cast<std::size_t>(info.dim);
    return {info.element_size, n, r.result.lie_kernel ? n : n * n};
  }
  const auto& p = std::get<ManifoldProblem>(r.problem);
  const ManifoldWidths w = manifold_widths(p, where);
  return {w.point, w.m, w.m * w.m};
}

ResultRecord read(const json& j, std::string_view where) {
  const Reader in(j, where);
  if (!j.is_object()) in.bad("result file", io::describe(j), "must be a JSON object");
  ResultRecord r;
  Result& x = r.result;
  x.status = in.word<Status>("status");
  const auto read_words = [&] {
    if (j.contains("message")) x.message = in.text("message");
    x.method = in.word<cartan::Method>("method");
    x.order = in.integer("order");
    if (!is_result_order(x.order)) in.bad("order", std::to_string(x.order), kResultOrderRule);
    if (j.contains("branch")) x.branch = in.text("branch");
  };
  // The order in which the keys are checked, so that the first bad one is named: a manifold's
  // words first, a group's problem first (as `cartan verify` always did).
  if (j.contains("manifold")) {
    read_words();
    r.problem = read_manifold_problem(in, r.tol);
  } else {
    r.problem = read_group_problem(in, r.tol);
    read_words();
  }
  const auto* group = std::get_if<GroupProblem>(&r.problem);
  x.lie_kernel = group != nullptr && lie_kernel(*group);
  const Widths w = widths(r, where);

  const json& t = in.key("t");
  if (!t.is_array() || (!t.empty() && t[0].is_array())) in.bad("t", io::describe(t), "must be a list of times");
  const std::vector<double> times = t.empty() ? std::vector<double>{} : io::json_numbers(t, where, "t");
  x.samples.t = Eigen::Map<const Eigen::VectorXd>(times.data(), static_cast<Eigen::Index>(times.size()));
  const std::size_t rows = times.size();
  x.samples.points = in.table(group ? "g" : "q", rows, w.point);
  x.samples.v = in.table("v", rows, w.n);
  x.samples.mu = in.table("mu", rows, w.n);
  x.samples.aux = in.table(x.lie_kernel ? "xi" : "Xi", rows, w.aux);
  if (const auto* m = std::get_if<ManifoldProblem>(&r.problem); m != nullptr && !m->frame0.empty()) {
    x.frame0 = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        m->frame0.data(), static_cast<Eigen::Index>(w.n), static_cast<Eigen::Index>(m->frame0.size() / w.n));
  }

  // The diagnostics: optional (a trajectory computed elsewhere can be verified); when absent,
  // NaN (unknown) and no iterations.
  x.terminal_error = j.contains("terminal_error") ? in.number_or_null("terminal_error") : kNaN;
  x.xi_terminal = j.contains("xi_terminal") ? in.number_or_null("xi_terminal") : kNaN;
  if (j.contains("iterations")) {
    const json& iterations = j["iterations"];
    if (!iterations.is_object()) in.bad("iterations", io::describe(iterations), "must be an object with outer, inner and sweeps");
    for (auto [name, count] : {std::pair{"outer", &x.outer_iterations}, {"inner", &x.inner_iterations}, {"sweeps", &x.sweeps}}) {
      const std::string key = std::string("iterations.") + name;
      if (!iterations.contains(name)) in.bad(key, "(missing)", "is required in a result file's iterations");
      *count = in.integer(iterations[name], key);
    }
  }
  x.action = j.contains("action") ? in.number_or_null("action") : kNaN;
  x.solve_time_s = j.contains("solve_time_s") ? in.number_or_null("solve_time_s") : kNaN;
  if (j.contains("mesh_size")) {
    CollocationReport c;
    c.mesh_size = in.integer("mesh_size");
    c.max_residual = in.number_or_null("max_residual");
    if (j.contains("group_defect")) c.group_defect = in.number_or_null("group_defect");
    x.collocation = c;
  }
  return r;
}

[[noreturn]] void bad_time(std::string_view where, Eigen::Index k, double value, const std::string& problem) {
  throw_invalid(where, "t[" + std::to_string(k) + "]", format_value(value), problem);
}

/// What the checks of a solution assume of its samples (read_solution).
void check_solution(const ResultRecord& r, std::string_view where) {
  const Samples& x = r.result.samples;
  const double T = std::visit([](const auto& p) { return p.T; }, r.problem);
  if (x.t.size() < 2) {
    throw_invalid(where, "t", "(an array of " + std::to_string(x.t.size()) + " entries)", "must be a list of at least 2 times");
  }
  for (Eigen::Index k = 1; k < x.t.size(); ++k) {
    if (!(x.t[k] > x.t[k - 1])) {
      bad_time(where, k, x.t[k],
               "is not greater than t[" + std::to_string(k - 1) + "] = " + format_value(x.t[k - 1]) + " (times must increase)");
    }
  }
  if (std::abs(x.t[0]) > kTimeSpanTolerance * T) bad_time(where, 0, x.t[0], "must be 0");
  const Eigen::Index last = x.t.size() - 1;
  if (std::abs(x.t[last] - T) > kTimeSpanTolerance * T) bad_time(where, last, x.t[last], "must equal T = " + format_value(T));
  const auto* group = std::get_if<GroupProblem>(&r.problem);
  const std::pair<const char*, const Table*> tables[] = {
      {group ? "g" : "q", &x.points}, {"v", &x.v}, {"mu", &x.mu}, {r.result.lie_kernel ? "xi" : "Xi", &x.aux}};
  for (const auto& [name, table] : tables) {
    for (Eigen::Index k = 0; k < table->rows(); ++k) {
      for (Eigen::Index i = 0; i < table->cols(); ++i) {
        if (!std::isfinite((*table)(k, i))) {
          throw_invalid(where, std::string(name) + "[" + std::to_string(k) + "][" + std::to_string(i) + "]",
                        format_value((*table)(k, i)), "is not finite");
        }
      }
    }
  }
  if (group == nullptr) return;
  const models::ModelInfo& info = group_info(*group, where);
  info.check_element(group->g0, where, "g0");
  info.check_element(group->gT, where, "gT");
  for (Eigen::Index k = 0; k < x.points.rows(); ++k) {
    const Eigen::RowVectorXd row = x.points.row(k);
    info.check_element(std::vector<double>(row.data(), row.data() + row.size()), where, "g[" + std::to_string(k) + "]");
  }
}

}  // namespace

nlohmann::json result_json(const ResultRecord& record) {
  const Result& r = record.result;
  json out = {{"status", to_string(r.status)}, {"message", r.message}, {"method", to_string(r.method)},
              {"order", r.order},             {"branch", r.branch},   {"tol", number_or_null(record.tol)}};
  std::visit([&](const auto& p) { write_problem(out, p); }, record.problem);
  const Samples& x = r.samples;
  out["t"] = json_list(x.t);
  out[record.on_manifold() ? "q" : "g"] = json_rows(x.points);
  out["v"] = json_rows(x.v);
  out["mu"] = json_rows(x.mu);
  out[r.lie_kernel ? "xi" : "Xi"] = json_rows(x.aux);
  if (r.frame0 && !out.contains("frame0")) out["frame0"] = json_rows(*r.frame0);  // the frame a solve chose
  out["terminal_error"] = number_or_null(r.terminal_error);
  out["xi_terminal"] = number_or_null(r.xi_terminal);
  out["iterations"] = {{"outer", r.outer_iterations}, {"inner", r.inner_iterations}, {"sweeps", r.sweeps}};
  out["action"] = number_or_null(r.action);  // the Lie-group kernel's S_h, else the action along the samples
  out["solve_time_s"] = number_or_null(r.solve_time_s);
  if (r.collocation) {
    out["mesh_size"] = r.collocation->mesh_size;
    out["max_residual"] = number_or_null(r.collocation->max_residual);
    if (std::isfinite(r.collocation->group_defect)) out["group_defect"] = r.collocation->group_defect;
  }
  return out;
}

ResultRecord read_result(const nlohmann::json& j, std::string_view where) {
  try {
    return read(j, where);
  } catch (const nlohmann::json::exception& e) {  // unreachable by the checks above; kept as a guarantee
    throw std::invalid_argument(std::string(where) + ": result file: " + e.what());
  }
}

ResultRecord read_solution(const nlohmann::json& j, std::string_view where) {
  ResultRecord r = read_result(j, where);
  check_solution(r, where);
  return r;
}

ResultRecord read_result_text(const std::string& text, std::string_view where) {
  return read_result(io::parse_json(text, std::string(where)), where);
}

std::string result_text(const ResultRecord& record) { return result_json(record).dump() + "\n"; }

}  // namespace cartan::api
