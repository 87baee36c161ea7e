#include "sweep_merge.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cartan/errors.hpp"
#include "cartan/api/json_io.hpp"
#include "sweep_table.hpp"

namespace cartan::cli {

namespace {

constexpr const char* kMergeWhere = "cartan merge";

std::string read_text(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw_invalid(kMergeWhere, "table", path, "is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_invalid(kMergeWhere, "table", path, "cannot be opened");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A row of some table: its grid index and where it came from (file, position in the file).
struct Located {
  std::size_t index, file, position;
};

/// The rows in grid order, after checking that no index repeats and none of 0 .. points - 1 is
/// missing (points: given, or the largest index + 1).
std::vector<Located> in_grid_order(std::vector<Located> rows, const std::vector<std::string>& paths,
                                   std::optional<std::size_t> points) {
  std::sort(rows.begin(), rows.end(), [](const Located& a, const Located& b) { return a.index < b.index; });
  const std::size_t n = points ? *points : rows.empty() ? 0 : rows.back().index + 1;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Located& row = rows[i];
    if (i > 0 && rows[i - 1].index == row.index) {
      throw_invalid(kMergeWhere, "grid index", std::to_string(row.index),
                    "appears twice (in " + paths[rows[i - 1].file] + " and " + paths[row.file] + ")");
    }
    if (row.index >= n) {
      throw_invalid(kMergeWhere, "grid index", std::to_string(row.index),
                    "(in " + paths[row.file] + ") is beyond the grid of " + std::to_string(n) + " points");
    }
  }
  if (rows.size() != n) {  // no repeats and all below n: some index is missing
    std::size_t missing = 0;
    while (missing < rows.size() && rows[missing].index == missing) ++missing;
    throw_invalid(kMergeWhere, "grid index", std::to_string(missing),
                  "is missing: " + std::to_string(n - rows.size()) + " of " + std::to_string(n) +
                      " points are in none of the tables (a shard left out?)");
  }
  return rows;
}

/// A shard's record {"k", "m", "grid_points"} (sweep_table.hpp, shard_json).
struct ShardRecord {
  std::size_t k, m, grid_points;
};

std::optional<ShardRecord> shard_of(const nlohmann::json& table, const std::string& path) {
  if (!table.contains("shard")) return {};
  const nlohmann::json& shard = table.at("shard");
  const auto field = [&](const char* key) {
    if (!shard.is_object() || !shard.contains(key) || !shard.at(key).is_number_unsigned()) {
      throw_invalid(kMergeWhere, "table", path, std::string("has a \"shard\" record without a count ") + key);
    }
    return shard.at(key).get<std::size_t>();
  };
  return ShardRecord{field("k"), field("m"), field("grid_points")};
}

/// The grid size the shards' records agree on, after checking that the tables are the shards
/// 1..M of one grid (each once), or nothing when no table is a shard.
std::optional<std::size_t> shards_complete(const std::vector<std::optional<ShardRecord>>& shards,
                                           const std::vector<std::string>& paths) {
  const auto first = std::find_if(shards.begin(), shards.end(), [](const auto& s) { return s.has_value(); });
  if (first == shards.end()) return {};
  const ShardRecord& one = **first;
  std::map<std::size_t, std::string> seen;  // k -> path
  for (std::size_t f = 0; f < shards.size(); ++f) {
    if (!shards[f]) throw_invalid(kMergeWhere, "table", paths[f], "is not a shard (no \"shard\" record) while others are");
    const ShardRecord& s = *shards[f];
    if (s.m != one.m || s.grid_points != one.grid_points) {
      throw_invalid(kMergeWhere, "table", paths[f],
                    "is shard " + std::to_string(s.k) + "/" + std::to_string(s.m) + " of a grid of " +
                        std::to_string(s.grid_points) + " points; " + paths[first - shards.begin()] + " is of " +
                        std::to_string(one.m) + " shards and " + std::to_string(one.grid_points) + " points");
    }
    if (!seen.emplace(s.k, paths[f]).second) {
      throw_invalid(kMergeWhere, "shard", std::to_string(s.k) + "/" + std::to_string(s.m),
                    "appears twice (" + seen.at(s.k) + " and " + paths[f] + ")");
    }
  }
  for (std::size_t k = 1; k <= one.m; ++k) {
    if (!seen.contains(k)) throw_invalid(kMergeWhere, "shard", std::to_string(k) + "/" + std::to_string(one.m), "is missing");
  }
  return one.grid_points;
}

std::string merge_json(const std::vector<std::string>& paths, const std::vector<std::string>& texts,
                       std::optional<std::size_t> points) {
  std::vector<nlohmann::json> tables;
  std::vector<std::optional<ShardRecord>> shards;
  std::vector<Located> rows;
  double wall_time_s = 0;
  for (std::size_t f = 0; f < paths.size(); ++f) {
    nlohmann::json table = io::parse_json(texts[f], std::string(kMergeWhere) + ": table = " + paths[f]);
    if (!table.is_object() || !table.contains("rows") || !table.at("rows").is_array() ||
        !table.contains("wall_time_s") || !table.at("wall_time_s").is_number()) {
      throw_invalid(kMergeWhere, "table", paths[f], "is not a JSON table of cartan sweep (an object with rows, wall_time_s)");
    }
    shards.push_back(shard_of(table, paths[f]));
    wall_time_s = std::max(wall_time_s, table.at("wall_time_s").get<double>());
    const nlohmann::json& list = table.at("rows");
    for (std::size_t r = 0; r < list.size(); ++r) {
      if (!list[r].is_object() || !list[r].contains("index") || !list[r].at("index").is_number_unsigned()) {
        throw_invalid(kMergeWhere, "table", paths[f], "has row " + std::to_string(r) + " without a grid index");
      }
      rows.push_back({list[r].at("index").get<std::size_t>(), f, r});
    }
    tables.push_back(std::move(table));
  }
  if (const auto grid_points = shards_complete(shards, paths)) {
    if (points && *points != *grid_points) {
      throw_invalid(kMergeWhere, "--points", std::to_string(*points),
                    "disagrees with the shards' grid of " + std::to_string(*grid_points) + " points");
    }
    points = grid_points;
  }
  std::vector<nlohmann::json> ordered;
  for (const Located& row : in_grid_order(std::move(rows), paths, points)) {
    ordered.push_back(std::move(tables[row.file].at("rows").at(row.position)));
  }
  return table_json(ordered, wall_time_s).dump() + "\n";
}

/// The records of a CSV text (RFC 4180: a line break inside a quoted field belongs to the record),
/// each without its line break.
std::vector<std::string> csv_records(const std::string& text) {
  std::vector<std::string> records;
  std::string record;
  bool quoted = false;
  for (char c : text) {
    if (c == '"') quoted = !quoted;  // a doubled quote toggles twice
    if (c == '\n' && !quoted) {
      records.push_back(std::move(record));
      record.clear();
    } else {
      record.push_back(c);
    }
  }
  if (!record.empty()) records.push_back(std::move(record));
  return records;
}

std::string merge_csv(const std::vector<std::string>& paths, const std::vector<std::string>& texts,
                      std::optional<std::size_t> points) {
  std::vector<std::vector<std::string>> files;
  std::vector<Located> rows;
  for (std::size_t f = 0; f < paths.size(); ++f) {
    std::vector<std::string> records = csv_records(texts[f]);
    if (records.empty() || records.front().rfind("index,", 0) != 0) {
      throw_invalid(kMergeWhere, "table", paths[f], "is not a table of cartan sweep (JSON, or CSV with the header index,...)");
    }
    if (f > 0 && records.front() != files.front().front()) {
      throw_invalid(kMergeWhere, "table", paths[f], "has another CSV header than " + paths.front());
    }
    for (std::size_t r = 1; r < records.size(); ++r) {
      const std::string field = records[r].substr(0, records[r].find(','));
      if (field.empty() || field.size() > 7 || field.find_first_not_of("0123456789") != std::string::npos) {
        throw_invalid(kMergeWhere, "table", paths[f],
                      "has line " + std::to_string(r + 1) + " without a grid index: " + quote_input(records[r]));
      }
      rows.push_back({std::stoul(field), f, r});
    }
    files.push_back(std::move(records));
  }
  std::string out = files.front().front() + "\n";
  for (const Located& row : in_grid_order(std::move(rows), paths, points)) out += files[row.file][row.position] + "\n";
  return out;
}

}  // namespace

std::string merge_tables(const std::vector<std::string>& paths, std::optional<std::size_t> points) {
  if (paths.empty()) throw std::invalid_argument("cartan merge: no tables given");
  std::vector<std::string> texts;
  for (const auto& path : paths) texts.push_back(read_text(path));
  const auto is_json = [](const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    return first != std::string::npos && text[first] == '{';
  };
  for (std::size_t f = 1; f < paths.size(); ++f) {
    if (is_json(texts[f]) != is_json(texts.front())) {
      throw_invalid(kMergeWhere, "table", paths[f], "is in another format (JSON or CSV) than " + paths.front());
    }
  }
  return is_json(texts.front()) ? merge_json(paths, texts, points) : merge_csv(paths, texts, points);
}

}  // namespace cartan::cli
