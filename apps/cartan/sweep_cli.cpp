// `cartan sweep`: the problem options of `cartan solve` (the base problem), a grid over lambda
// and/or the endpoint (sweep_grid.cpp), solved on a pool of threads (sweep_run.cpp) into one
// JSON or CSV table (sweep_table.cpp); with --shard K/M only the K-th of M interleaved parts
// (sweep_grid.hpp, Shard), whose tables `cartan merge` joins (sweep_merge.cpp).
#include <algorithm>
#include <chrono>
#include <memory>
#include <thread>
#include <unistd.h>

#include <Eigen/Core>

#include "command.hpp"
#include "output.hpp"
#include "problem_options.hpp"
#include "solve_command.hpp"
#include "sweep_run.hpp"
#include "sweep_table.hpp"

namespace cartan::cli {

namespace {

struct SweepFlags {
  ProblemFlags problem;
  GridFlags grid;
  unsigned jobs = std::max(std::thread::hardware_concurrency(), 1u);
  std::string format = "json", output, shard;
  bool trajectories = false, quiet = false;
};

/// Solves one point (none once interrupted: the sweep then writes nothing); anything it throws
/// becomes an error row. Returns whether the point failed.
bool solve_into(std::size_t index, const GridPoint& point, bool trajectories, nlohmann::json& row) noexcept {
  if (interrupted()) return true;
  try {
    const nlohmann::json result = solve(point.spec, interruptible(SolveMonitor()));
    if (interrupted()) return true;  // an interrupted result has no trajectory (result_json in solve_command.hpp)
    row = result_row(index, point, result, trajectories);
  } catch (const std::invalid_argument& e) {  // boundary data solve() rejects, e.g. a gT that is no rotation
    row = error_row(index, point, retitled(e, "cartan sweep: grid point " + std::to_string(index)).what());
  } catch (const std::exception& e) {
    row = error_row(index, point, e.what());
  } catch (...) {
    row = error_row(index, point, "unknown exception");
  }
  return row_failed(row);
}

int run_sweep(const CLI::App& command, SweepFlags& flags) {
  const Shard shard = command.count("--shard") == 0 ? Shard{} : parse_shard(flags.shard);
  std::vector<GridPoint> points;
  try {
    points = build_grid(problem_from(command, flags.problem), flags.grid);
  } catch (const std::invalid_argument& e) {
    throw retitled(e, "cartan sweep");
  }
  std::vector<std::size_t> mine;  // the grid indices of this shard
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (shard.contains(i)) mine.push_back(i);
  }
  if (!flags.output.empty()) require_writable(flags.output, "cartan sweep: --output");  // before hours of solving

  Eigen::initParallel();  // Eigen's documented step before calling it from several threads
  const auto start = std::chrono::steady_clock::now();
  std::vector<nlohmann::json> rows(mine.size());
  ProgressReport report(mine.size(), isatty(STDERR_FILENO) != 0);
  run_in_parallel(
      mine.size(), flags.jobs,
      [&](std::size_t r) { return solve_into(mine[r], points[mine[r]], flags.trajectories, rows[r]); },
      flags.quiet ? nullptr : &report);
  const double wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (interrupted()) return exit_interrupted("cartan sweep");

  std::string text;
  if (flags.format == "csv") {
    text = table_csv(rows);
  } else {
    nlohmann::json table = table_json(rows, wall_time_s);
    if (!shard.whole()) table["shard"] = shard_json(shard, points.size());
    text = table.dump() + "\n";
  }
  if (!write_output(text, flags.output, "cartan sweep: --output")) return exit_interrupted("cartan sweep");
  const bool any_failed = std::any_of(rows.begin(), rows.end(), row_failed);
  return any_failed ? kExitFailed : kExitConverged;
}

}  // namespace

Command add_sweep_command(CLI::App& tool) {
  auto* sweep = tool.add_subcommand("sweep", "Solve a grid of problems (lambda and/or endpoints; a group model or any space) in parallel into one table");
  sweep->footer(
      "The base problem takes every option of `cartan solve`; each grid point replaces lambda and/or the\n"
      "endpoint (the Cartesian product of the lambda list and the endpoint list), or applies one object of\n"
      "a --grid file. Every point is validated before anything is solved. Rows are in grid order whatever --jobs.\n"
      "Examples:\n"
      "  cartan sweep --model free-rigid-body --T 50 --N 1000 --a0 -1,-1,-1 --aT 0.9,1,1 --tol 1e-8 --lambda-range 0:1:11\n"
      "  cartan sweep --model oscillator --T 3 --N 300 --a0=-1,-1,-1 --lambdas 0,0.5,1 --aT-list \"1,0,0;0,1,0\" --format csv\n"
      "  cartan sweep --group heisenberg --model oscillator --T 1 --N 200 --gT-list \"1,0.5,0.8;0,1,0\" --jobs 2\n"
      "  cartan sweep --manifold sphere --q0 1,0,-0.3 --gravity 9.81 --T 1 --N 200 --qT-list \"0,1,-0.5;0,1,0.5\"\n"
      "  cartan sweep --problem base.json --grid points.json --output table.json   # points.json: [{\"lambda\": 0}, {\"T\": 2}]\n"
      "Across machines: each solves one shard, `cartan merge` joins the tables into the unsharded one:\n"
      "  cartan sweep ... --shard 1/3 --format csv --output part1.csv   # points 0, 3, 6, ...\n"
      "  cartan merge part1.csv part2.csv part3.csv > all.csv\n"
      "Exit codes: 0 every point converged, 1 some point failed (the table is still written), 2 bad input,\n"
      "130 interrupted (SIGINT: the running solves stop, no output written).");
  auto flags = std::make_shared<SweepFlags>();
  add_problem_options(*sweep, flags->problem);
  GridFlags& grid = flags->grid;
  sweep->add_option("--lambdas", grid.lambdas, "grid: lambda values, e.g. 0,0.5,1");
  sweep->add_option("--lambda-range", grid.lambda_range,
                    "grid: START:STOP:COUNT, COUNT evenly spaced lambdas from START to STOP (after --lambdas)");
  sweep->add_option("--aT-list", grid.aT_list, "grid (so3, with --a0): final directions \"x,y,z;x,y,z;...\"");
  sweep->add_option("--gT-list", grid.gT_list,
                    "grid: final elements separated by \";\", each written as --gT (heisenberg: \"a,b,c;a,b,c\"; so3, se2: 9 numbers row-major; se3: 16)");
  sweep->add_option("--qT-list", grid.qT_list,
                    "grid (--manifold): final points separated by \";\", each written as --qT (sphere: \"x,y,z;x,y,z\")");
  sweep->add_option("--grid", grid.grid_file,
                    "JSON file: an array of objects of problem keys, each overriding the base problem (instead of the "
                    "grid flags)");
  sweep->add_option("--jobs", flags->jobs, "threads (default: the number of cores, here " +
                                               std::to_string(flags->jobs) + ")")
      ->check(CLI::Range(1u, 4096u));
  sweep->add_option("--format", flags->format, "json | csv (default json)")->check(CLI::IsMember({"json", "csv"}));
  sweep->add_option("--output", flags->output, "table file (default stdout)");
  sweep->add_option("--shard", flags->shard,
                    "K/M: solve only the K-th of M interleaved parts of the grid, the points with index mod M = K - 1 "
                    "(rows keep their grid index; `cartan merge` joins the parts)");
  sweep->add_flag("--trajectories", flags->trajectories, "include t, g, v in each JSON row (off: the table stays small)");
  sweep->add_flag("--quiet", flags->quiet, "no progress report on stderr");
  return {sweep, [sweep, flags] { return run_sweep(*sweep, *flags); }};
}

}  // namespace cartan::cli
