// `cartan solve`: the problem options (problem_options.cpp), --output, and the solve itself
// (solve_command.cpp).
#include <memory>

#include "command.hpp"
#include "json_io.hpp"
#include "problem_options.hpp"
#include "solve_command.hpp"

namespace cartan::cli {

namespace {

int run_solve(const CLI::App& command, ProblemFlags& flags) {
  ProblemSpec spec = problem_from(command, flags);
  validate(spec);
  const nlohmann::json result = solve(spec);
  write_json(result, spec.output, "cartan solve: --output");
  return result["status"] == "converged" ? kExitConverged : kExitFailed;
}

}  // namespace

Command add_solve_command(CLI::App& tool) {
  auto* solve = tool.add_subcommand("solve", "Solve the transported-velocity boundary-value problem (paper eq:reduced-system)");
  solve->footer(
      "Examples:\n"
      "  cartan solve --model free-rigid-body --lambda 0.5 --T 50 --N 1000 --a0 -1,-1,-1 --aT 0.9,1,1 --tol 1e-8\n"
      "  cartan solve --model oscillator --lambda 0 --T 12 --N 800 --a0=-0.7,-1,-0.7 --aT 0.8,0.8,1 --tol 1e-6\n"
      "  cartan solve --group heisenberg --model oscillator --lambda 0.5 --T 1 --N 200 --gT 1,0.5,0.8\n"
      "  cartan solve --problem problem.json --output result.json\n"
      "Exit codes: 0 converged, 1 solver failed (JSON still written), 2 bad input.");
  auto flags = std::make_shared<ProblemFlags>();
  add_problem_options(*solve, *flags);
  solve->add_option("--output", flags->spec.output, "output file (default stdout)");
  return {solve, [solve, flags] { return run_solve(*solve, *flags); }};
}

}  // namespace cartan::cli
