#pragma once
// The result table of `cartan sweep`: one row per grid point (JSON object), and the whole table
// as JSON or CSV (docs/reference.md, "cartan sweep").

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sweep_grid.hpp"

namespace cartan::cli {

/// The row of point `index` from its `cartan solve` result: index, lambda, aT or gT, (overrides,)
/// status, message, method, branch, terminal_error, iterations, solve_time_s, v0, and t, g, v
/// when `trajectories`.
nlohmann::json result_row(std::size_t index, const GridPoint& point, const nlohmann::json& result, bool trajectories);

/// The row of a point whose solve threw: status "error", the message, and null diagnostics.
nlohmann::json error_row(std::size_t index, const GridPoint& point, const std::string& message);

/// A row counts as failed unless its status is "converged".
bool row_failed(const nlohmann::json& row);

/// {"points", "converged", "failed": [indices], "rows", "wall_time_s"}.
nlohmann::json table_json(const std::vector<nlohmann::json>& rows, double wall_time_s);

/// What a shard's JSON table records about its part of the grid: {"k", "m", "grid_points"}
/// (`cartan merge` checks with it that the parts make up the whole grid).
nlohmann::json shard_json(const Shard& shard, std::size_t grid_points);

/// A header line and one line per row with the scalar columns of the rows (v0 as v0_1..v0_n, n
/// the longest v0 of the rows and at least 3; the endpoint as its key and its numbers separated by spaces), numbers with the fewest digits that read back exactly;
/// text fields are quoted as RFC 4180 requires.
std::string table_csv(const std::vector<nlohmann::json>& rows);

}  // namespace cartan::cli
