#pragma once
// `cartan merge`: the tables of the shards of a sweep (`cartan sweep --shard K/M`) joined into the
// table of the unsharded sweep, rows in grid order. JSON tables (the sweep's default) carry their
// shard and the grid's size, so the merge checks that the shards 1..M of one grid are all there;
// CSV tables carry only the rows, so the grid's size is --points N or else the largest index + 1.

#include <optional>
#include <string>
#include <vector>

namespace cartan::cli {

/// The merged table as text (JSON: one line; CSV: the common header line, then the rows). Every
/// file must be a table of `cartan sweep` in the same format (JSON or CSV, told by the first
/// character); CSV headers must agree; no grid index may appear twice or be missing from
/// 0 .. points - 1. The merged JSON table's wall_time_s is the largest of the shards'. Throws
/// std::invalid_argument ("cartan merge: ...", naming the file and the index) otherwise.
std::string merge_tables(const std::vector<std::string>& paths, std::optional<std::size_t> points);

}  // namespace cartan::cli
