#include "sweep_table.hpp"

#include <algorithm>
#include <sstream>

#include "cartan/errors.hpp"

namespace cartan::cli {

namespace {

/// The row's identity: which point it is.
nlohmann::json row_head(std::size_t index, const GridPoint& point) {
  const ProblemSpec& s = point.spec;
  // lambda is Cartan–Schouten's parameter: null under another connection, which the row names.
  nlohmann::json row = {{"index", index}, {"lambda", is_general_connection(s) ? nlohmann::json() : nlohmann::json(s.lambda)}};
  if (is_general_connection(s)) row["connection"] = s.connection;
  if (is_manifold_problem(s)) {
    row["manifold"] = s.manifold;
    row["qT"] = s.qT;
  } else if (s.aT.empty()) {
    row["gT"] = s.gT;
  } else {
    row["aT"] = s.aT;
  }
  if (!point.overrides.empty()) row["overrides"] = point.overrides;
  return row;
}

std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    out.push_back(c);
    if (c == '"') out.push_back('"');  // a quote inside a quoted field is doubled
  }
  out.push_back('"');
  return out;
}

/// A number with the fewest digits that read back exactly (format_value), a string as text, null as an empty field.
std::string csv_field(const nlohmann::json& value) {
  if (value.is_null()) return "";
  if (value.is_string()) return csv_text(value.get<std::string>());
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  return format_value(value.get<double>());
}

/// The numbers of a list separated by spaces (one CSV field).
std::string csv_numbers(const nlohmann::json& values) {
  std::ostringstream out;
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << csv_field(values[i]);
  return out.str();
}

/// The rows of a frame, row after row, separated by spaces (one CSV field); empty where the row
/// has none (a group model's, an error row).
std::string csv_frame(const nlohmann::json& row) {
  if (!row.contains("frame0") || !row.at("frame0").is_array()) return "";
  std::string out;
  for (const auto& e : row.at("frame0")) out += (out.empty() ? "" : " ") + csv_numbers(e);
  return out;
}

/// `parent[key]`, or an empty field when parent is null (the diagnostics of an error row).
std::string csv_member(const nlohmann::json& parent, const nlohmann::json::object_t::key_type& key) {
  return parent.is_null() ? std::string() : csv_field(parent.at(key));
}

std::string csv_element(const nlohmann::json& list, std::size_t i) {
  return list.is_null() ? std::string() : csv_field(list.at(i));
}

}  // namespace

nlohmann::json result_row(std::size_t index, const GridPoint& point, const nlohmann::json& result, bool trajectories) {
  nlohmann::json row = row_head(index, point);
  for (const char* key : {"status", "message", "method", "branch", "terminal_error", "iterations", "solve_time_s"}) {
    row[key] = result.at(key);
  }
  row["v0"] = result.at("v").at(0);
  row["action"] = result.at("action");  // result_json writes it always (null where there is none)
  if (result.contains("frame0")) row["frame0"] = result.at("frame0");  // the frame v0 is in (a manifold's)
  if (trajectories) {
    for (const char* key : {"t", result.contains("q") ? "q" : "g", "v"}) row[key] = result.at(key);
  }
  return row;
}

nlohmann::json error_row(std::size_t index, const GridPoint& point, const std::string& message) {
  nlohmann::json row = row_head(index, point);
  row["status"] = "error";
  row["message"] = message;
  row["method"] = point.spec.method;
  for (const char* key : {"branch", "terminal_error", "iterations", "solve_time_s", "action", "v0"}) row[key] = nullptr;
  return row;
}

bool row_failed(const nlohmann::json& row) { return row.at("status") != "converged"; }

nlohmann::json table_json(const std::vector<nlohmann::json>& rows, double wall_time_s) {
  nlohmann::json failed = nlohmann::json::array();
  for (const auto& row : rows) {
    if (row_failed(row)) failed.push_back(row.at("index"));
  }
  return {{"points", rows.size()}, {"converged", rows.size() - failed.size()}, {"failed", failed},
          {"rows", rows}, {"wall_time_s", wall_time_s}};
}

nlohmann::json shard_json(const Shard& shard, std::size_t grid_points) {
  return {{"k", shard.k}, {"m", shard.m}, {"grid_points", grid_points}};
}

std::string table_csv(const std::vector<nlohmann::json>& rows) {
  // v0 has the space's dimension (2 on the sphere, 6 on se3): as many columns as the longest v0 of
  // the rows, the shorter ones (other groups of a --grid, error rows) padded with empty fields.
  std::size_t width = 0;
  for (const auto& row : rows) {
    if (row.at("v0").is_array()) width = std::max(width, row.at("v0").size());
  }
  std::ostringstream out;
  out << "index,lambda,endpoint_key,endpoint,status,message,method,branch,terminal_error,iterations_outer,"
         "iterations_inner,iterations_sweeps,solve_time_s,action,frame0";
  for (std::size_t i = 1; i <= width; ++i) out << ",v0_" << i;
  out << '\n';
  for (const auto& row : rows) {
    const char* endpoint = row.contains("aT") ? "aT" : row.contains("qT") ? "qT" : "gT";
    const auto& iterations = row.at("iterations");
    const auto& v0 = row.at("v0");
    out << csv_field(row.at("index")) << ',' << csv_field(row.at("lambda")) << ',' << endpoint << ','
        << csv_numbers(row.at(endpoint)) << ',' << csv_field(row.at("status")) << ',' << csv_field(row.at("message"))
        << ',' << csv_field(row.at("method")) << ',' << csv_field(row.at("branch")) << ','
        << csv_field(row.at("terminal_error")) << ',' << csv_member(iterations, "outer") << ','
        << csv_member(iterations, "inner") << ',' << csv_member(iterations, "sweeps") << ','
        << csv_field(row.at("solve_time_s")) << ','
        << csv_field(row.contains("action") ? row.at("action") : nlohmann::json(nullptr))  // tables before the column
        << ',' << csv_frame(row);  // the frame v0 is in (a manifold's, which turns with qT)
    for (std::size_t i = 0; i < width; ++i) out << ',' << (i < v0.size() ? csv_element(v0, i) : std::string());
    out << '\n';
  }
  return out.str();
}

}  // namespace cartan::cli
