#include "sweep_grid.hpp"

#include <cmath>
#include <optional>
#include <sstream>

#include "cartan/errors.hpp"
#include "cartan/api/json_io.hpp"

namespace cartan::cli {

namespace {

constexpr const char* kGridWhere = "cartan sweep";

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();  // a trailing separator is an empty item
  return parts;
}

/// "START:STOP:COUNT" -> COUNT evenly spaced values, the last one exactly STOP.
std::vector<double> lambda_range(const std::string& text) {
  const auto bad = [&](const std::string& problem) { throw_invalid(kGridWhere, "lambda-range", "\"" + text + "\"", problem); };
  const auto parts = split(text, ':');
  if (parts.size() != 3) bad("must be START:STOP:COUNT");
  const auto number = [&](const std::string& part) {
    std::vector<double> x;
    try {
      x = io::parse_list(part, "lambda-range");
    } catch (const std::invalid_argument&) {
      bad("must be START:STOP:COUNT (three numbers)");
    }
    if (x.size() != 1) bad("must be START:STOP:COUNT (three numbers)");
    return x[0];
  };
  const double start = number(parts[0]), stop = number(parts[1]), count = number(parts[2]);
  if (!std::isfinite(start) || !std::isfinite(stop)) bad("has a non-finite end");
  if (!(count >= 1 && count <= static_cast<double>(kMaxGridPoints) && std::floor(count) == count)) {
    bad("has COUNT not an integer between 1 and " + std::to_string(kMaxGridPoints));
  }
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> values(n, start);
  for (std::size_t i = 1; i < n; ++i) {
    values[i] = i + 1 == n ? stop : start + (stop - start) * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  return values;
}

/// "x,y,z;x,y,z" -> one list of numbers per ';'-separated item.
std::vector<std::vector<double>> endpoint_list(const std::string& text, const std::string& name) {
  std::vector<std::vector<double>> out;
  for (const auto& item : split(text, ';')) out.push_back(io::parse_list(item, name));
  return out;
}

/// Applies a --grid file's entries to the base problem.
std::vector<GridPoint> file_points(const ProblemSpec& base, const std::string& path) {
  const nlohmann::json file = io::read_json_file(path, "cartan sweep: --grid");
  if (!file.is_array() || file.empty()) {
    throw_invalid(kGridWhere, "--grid", path, "must hold a non-empty JSON array of objects of problem keys");
  }
  if (file.size() > kMaxGridPoints) {
    throw_invalid(kGridWhere, "--grid", path, "has more than " + std::to_string(kMaxGridPoints) + " points");
  }
  std::vector<GridPoint> points;
  for (std::size_t i = 0; i < file.size(); ++i) {
    const std::string where = "cartan sweep: --grid entry " + std::to_string(i);
    if (file[i].is_object() && file[i].contains("output")) {
      throw_invalid(where, "key \"output\"", file[i]["output"].dump(), "is not a grid key (the sweep writes one table: --output)");
    }
    GridPoint point{base, file[i]};
    try {
      apply_json(point.spec, file[i]);
    } catch (const std::invalid_argument& e) {
      throw retitled(e, where);
    }
    points.push_back(std::move(point));
  }
  return points;
}

/// The Cartesian product of the lambda list and the endpoint list (either may be absent).
std::vector<GridPoint> flag_points(const ProblemSpec& base, const GridFlags& flags) {
  const int lists = int(!flags.aT_list.empty()) + int(!flags.gT_list.empty()) + int(!flags.qT_list.empty());
  if (lists > 1) {
    throw_invalid(kGridWhere, "--aT-list/--gT-list/--qT-list",
                  flags.aT_list + " / " + flags.gT_list + " / " + flags.qT_list, "conflict: give one");
  }
  // Each problem's own endpoint: a group model's final element or direction, a manifold's point.
  if (is_manifold_problem(base) && lists == 1 && flags.qT_list.empty()) {
    const bool directions = !flags.aT_list.empty();
    throw_invalid(kGridWhere, directions ? "--aT-list" : "--gT-list",
                  quote_input(directions ? flags.aT_list : flags.gT_list),
                  "is a group model's endpoint; a manifold's final point is --qT: give --qT-list");
  }
  if (!is_manifold_problem(base) && !flags.qT_list.empty()) {
    throw_invalid(kGridWhere, "--qT-list", quote_input(flags.qT_list),
                  "is a manifold's final point (with --manifold); a group model's is --gT-list or --aT-list");
  }
  std::vector<double> lambdas;
  if (!flags.lambdas.empty()) lambdas = io::parse_list(flags.lambdas, "lambdas");
  if (!flags.lambda_range.empty()) {
    const auto range = lambda_range(flags.lambda_range);
    lambdas.insert(lambdas.end(), range.begin(), range.end());
  }
  const bool directions = !flags.aT_list.empty(), points_of_manifold = !flags.qT_list.empty();
  const auto endpoints = directions           ? endpoint_list(flags.aT_list, "aT-list")
                         : points_of_manifold ? endpoint_list(flags.qT_list, "qT-list")
                         : !flags.gT_list.empty() ? endpoint_list(flags.gT_list, "gT-list")
                                                  : std::vector<std::vector<double>>{};
  if (lambdas.empty() && endpoints.empty()) {
    throw std::invalid_argument(
        "cartan sweep: no grid: give --lambdas, --lambda-range, --aT-list, --gT-list, --qT-list or --grid (see cartan "
        "sweep --help)");
  }
  const std::size_t n_lambda = std::max<std::size_t>(lambdas.size(), 1);
  const std::size_t n_end = std::max<std::size_t>(endpoints.size(), 1);
  if (n_lambda * n_end > kMaxGridPoints) {
    throw_invalid(kGridWhere, "grid size", std::to_string(n_lambda) + " x " + std::to_string(n_end),
                  "is more than " + std::to_string(kMaxGridPoints) + " points");
  }
  std::vector<GridPoint> points;
  for (std::size_t i = 0; i < n_lambda; ++i) {
    for (std::size_t j = 0; j < n_end; ++j) {
      GridPoint point{base};
      if (!lambdas.empty()) {
        point.spec.lambda = lambdas[i];
        point.spec.given.emplace_back("lambda");  // so that validate refuses it on another connection
      }
      if (!endpoints.empty()) (directions ? point.spec.aT : points_of_manifold ? point.spec.qT : point.spec.gT) = endpoints[j];
      points.push_back(std::move(point));
    }
  }
  return points;
}

/// A whole number in [1, kMaxGridPoints] written with digits only, or nothing.
std::optional<std::size_t> count_of(const std::string& text) {
  if (text.empty() || text.size() > 7 || text.find_first_not_of("0123456789") != std::string::npos) return {};
  const std::size_t n = std::stoul(text);
  if (n < 1 || n > kMaxGridPoints) return {};
  return n;
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const auto parts = split(text, '/');
  const auto k = parts.size() == 2 ? count_of(parts[0]) : std::nullopt;
  const auto m = parts.size() == 2 ? count_of(parts[1]) : std::nullopt;
  if (!k || !m || *k > *m) {
    throw_invalid(kGridWhere, "--shard", quote_input(text),
                  "must be K/M, two integers with 1 <= K <= M <= " + std::to_string(kMaxGridPoints) +
                      " (the K-th of M shards)");
  }
  return {*k, *m};
}

std::invalid_argument retitled(const std::invalid_argument& error, const std::string& where) {
  const std::string message = error.what();
  const std::string shared = "cartan solve: ";
  if (message.rfind(shared, 0) == 0) return std::invalid_argument(where + ": " + message.substr(shared.size()));
  if (message.rfind(kGridWhere, 0) == 0) return error;  // already a sweep message
  return std::invalid_argument(where + ": " + message);
}

std::vector<GridPoint> build_grid(const ProblemSpec& base, const GridFlags& flags) {
  const bool from_flags = !(flags.lambdas.empty() && flags.lambda_range.empty() && flags.aT_list.empty() &&
                            flags.gT_list.empty() && flags.qT_list.empty());
  if (from_flags && !flags.grid_file.empty()) {
    throw_invalid(kGridWhere, "--grid", flags.grid_file,
                  "conflicts with --lambdas/--lambda-range/--aT-list/--gT-list/--qT-list (give the whole grid in the file)");
  }
  std::vector<GridPoint> points;
  try {
    points = flags.grid_file.empty() ? flag_points(base, flags) : file_points(base, flags.grid_file);
  } catch (const std::invalid_argument& e) {
    throw retitled(e, kGridWhere);
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    try {
      validate(points[i].spec);
    } catch (const std::invalid_argument& e) {
      throw retitled(e, "cartan sweep: grid point " + std::to_string(i));
    }
  }
  return points;
}

}  // namespace cartan::cli
