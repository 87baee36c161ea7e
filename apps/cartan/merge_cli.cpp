// `cartan merge TABLE...`: the tables of the shards of a sweep (`cartan sweep --shard K/M`)
// joined into the table of the unsharded sweep (sweep_merge.cpp).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "output.hpp"
#include "sweep_merge.hpp"
#include "sweep_table.hpp"

namespace cartan::cli {

namespace {

struct MergeFlags {
  std::vector<std::string> tables;
  std::size_t points = 0;  ///< 0: not given
  std::string output;
};

}  // namespace

Command add_merge_command(CLI::App& tool) {
  auto* merge = tool.add_subcommand("merge", "Join the tables of the shards of a sweep (cartan sweep --shard K/M)");
  merge->footer(
      "Rows are written in grid order, so that the merged table is the table of the unsharded sweep (but for the\n"
      "timings solve_time_s and wall_time_s, here the largest of the shards'). The tables must all be JSON or all CSV,\n"
      "with the same CSV header; no grid index may appear twice or be missing. A JSON shard records its K/M and the\n"
      "grid's size, so every shard must be given; a CSV table does not: --points N checks for indices 0 .. N-1\n"
      "(default: up to the largest index found).\n"
      "Examples:\n"
      "  cartan sweep --model oscillator --T 3 --N 300 --a0=-1,-1,-1 --aT 1,0.2,0.1 --lambda-range 0:1:101 --shard 2/3 > part2.json\n"
      "  cartan merge part1.json part2.json part3.json > all.json\n"
      "  cartan merge --points 101 part1.csv part2.csv part3.csv --output all.csv\n"
      "Exit codes: 0 the table was written, 2 bad input (one line on stderr naming the file or the grid index),\n"
      "130 interrupted (SIGINT: no output written).");
  auto flags = std::make_shared<MergeFlags>();
  merge->add_option("tables", flags->tables, "the shards' tables (JSON or CSV files of cartan sweep)")->required();
  merge->add_option("--points", flags->points, "CSV: the grid's number of points (indices 0 .. N-1 must all be there)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000}));
  merge->add_option("--output", flags->output, "merged table file (default stdout)");
  return {merge, [flags] {
            const std::optional<std::size_t> points =
                flags->points == 0 ? std::nullopt : std::optional<std::size_t>(flags->points);
            if (!flags->output.empty()) require_writable(flags->output, "cartan merge: --output");
            const std::string table = merge_tables(flags->tables, points);
            if (!write_output(table, flags->output, "cartan merge: --output")) return exit_interrupted("cartan merge");
            return kExitConverged;
          }};
}

}  // namespace cartan::cli
