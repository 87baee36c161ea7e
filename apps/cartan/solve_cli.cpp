// `cartan solve`: the problem options (problem_options.cpp), --output, and the solve itself
// (solve_command.cpp).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "output.hpp"
#include "problem_options.hpp"
#include "cartan/status.hpp"
#include "solve_command.hpp"

namespace cartan::cli {

namespace {

/// The monitor of `cartan solve`: stops on SIGINT; with --progress, one line per iteration on stderr.
SolveMonitor cli_monitor(bool progress) {
  SolveMonitor::ProgressCallback report;
  if (progress) {
    report = [](const Progress& p) {
      std::fprintf(stderr, "cartan solve: %.*s, iteration %d, residual %.3e\n", static_cast<int>(p.stage.size()),
                   p.stage.data(), p.iteration, p.residual);
    };
  }
  return interruptible(SolveMonitor(report, {}));
}

int run_solve(const CLI::App& command, ProblemFlags& flags, bool progress) {
  ProblemSpec spec = problem_from(command, flags);
  validate(spec);
  if (!spec.output.empty()) require_writable(spec.output, "cartan solve: --output");
  const nlohmann::json result = solve(spec, cli_monitor(progress));
  if (result["status"] == std::string(to_string(Status::Interrupted)) ||
      !write_output(result.dump() + "\n", spec.output, "cartan solve: --output")) {
    return exit_interrupted("cartan solve");
  }
  return result["status"] == std::string(to_string(Status::Converged)) ? kExitConverged : kExitFailed;
}

}  // namespace

Command add_solve_command(CLI::App& tool) {
  auto* solve = tool.add_subcommand("solve", "Solve the transported-velocity boundary-value problem (paper eq:reduced-system)");
  solve->footer(
      "Examples:\n"
      "  cartan solve --model free-rigid-body --lambda 0.5 --T 50 --N 1000 --a0 -1,-1,-1 --aT 0.9,1,1 --tol 1e-8\n"
      "  cartan solve --model oscillator --lambda 0 --T 12 --N 800 --a0=-0.7,-1,-0.7 --aT 0.8,0.8,1 --tol 1e-6\n"
      "  cartan solve --group heisenberg --model oscillator --lambda 0.5 --T 1 --N 200 --gT 1,0.5,0.8\n"
      "  cartan solve --group se2 --T 1 --N 100 --gT 0,-1,1,1,0,-0.5,0,0,1 --inertia 1,0.1,0,0.1,1,0,0,0,0.5\n"
      "  cartan solve --group se3 --T 1 --N 100 --gT 1,0,0,0.5,0,0,-1,0.2,0,1,0,-0.3,0,0,0,1\n"
      "  cartan solve --problem problem.json --output result.json\n"
      "Exit codes: 0 converged, 1 solver failed (JSON still written), 2 bad input, 130 interrupted (SIGINT;\n"
      "no output written).");
  auto flags = std::make_shared<ProblemFlags>();
  auto progress = std::make_shared<bool>(false);
  add_problem_options(*solve, *flags);
  solve->add_option("--output", flags->spec.output, "output file (default stdout)");
  solve->add_flag("--progress", *progress, "report every iteration (stage, iteration, residual) on stderr");
  return {solve, [solve, flags, progress] { return run_solve(*solve, *flags, *progress); }};
}

}  // namespace cartan::cli
