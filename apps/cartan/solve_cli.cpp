// `cartan solve`: the options of the CLI contract (README.md), a JSON problem file, and the
// solve itself (solve_command.cpp).
#include <fstream>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "json_io.hpp"
#include "problem_spec.hpp"
#include "solve_command.hpp"

namespace cartan::cli {

namespace {

/// What the flags of `cartan solve` hold until the command line has been parsed.
struct SolveFlags {
  ProblemSpec spec;
  std::string problem_file, inertia, g0, gT, a0, aT;
};

/// Copies the fields named by the flags given on the command line from `flags` into `spec`.
void override_with_flags(ProblemSpec& spec, const ProblemSpec& flags, const std::vector<std::string>& given) {
  for (const auto& flag : given) {
    if (flag == "group") spec.group = flags.group;
    if (flag == "model") spec.model = flags.model;
    if (flag == "inertia") spec.inertia = flags.inertia;
    if (flag == "lambda") spec.lambda = flags.lambda;
    if (flag == "T") spec.T = flags.T;
    if (flag == "N") spec.N = flags.N;
    if (flag == "g0") spec.g0 = flags.g0;
    if (flag == "gT") spec.gT = flags.gT;
    if (flag == "a0") spec.a0 = flags.a0;
    if (flag == "aT") spec.aT = flags.aT;
    if (flag == "method") spec.method = flags.method;
    if (flag == "order") spec.order = flags.order;
    if (flag == "tol") spec.tol = flags.tol;
    if (flag == "samples") spec.samples = flags.samples;
    if (flag == "segments") spec.segments = flags.segments;
    if (flag == "continuation") spec.continuation = flags.continuation;
    if (flag == "max-iterations") spec.max_iterations = flags.max_iterations;
    if (flag == "output") spec.output = flags.output;
  }
}

int run_solve(const CLI::App& command, SolveFlags& flags) {
  std::vector<std::string> given;
  for (const auto* opt : command.get_options()) {
    if (opt->count() > 0) given.push_back(opt->get_name().substr(2));
  }
  if (!flags.inertia.empty()) flags.spec.inertia = parse_list(flags.inertia, "inertia");
  if (!flags.g0.empty()) flags.spec.g0 = parse_list(flags.g0, "g0");
  if (!flags.gT.empty()) flags.spec.gT = parse_list(flags.gT, "gT");
  if (!flags.a0.empty()) flags.spec.a0 = parse_list(flags.a0, "a0");
  if (!flags.aT.empty()) flags.spec.aT = parse_list(flags.aT, "aT");

  ProblemSpec spec;
  if (!flags.problem_file.empty()) apply_json(spec, read_json_file(flags.problem_file, "cartan solve: --problem"));
  override_with_flags(spec, flags.spec, given);  // flags override the file
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
  auto flags = std::make_shared<SolveFlags>();
  ProblemSpec& f = flags->spec;
  solve->add_option("--problem", flags->problem_file, "JSON problem file (keys as the flags; flags override it)");
  solve->add_option("--group", f.group, "so3 | heisenberg (default so3)");
  solve->add_option("--model", f.model, "free-rigid-body | oscillator (default free-rigid-body)");
  solve->add_option("--inertia", flags->inertia, "I1,I2,I3 (default 2,3,4 for so3, 1,1,1 for heisenberg)");
  solve->add_option("--lambda", f.lambda, "Cartan-Schouten parameter (any real; default 0.5)");
  solve->add_option("--T", f.T, "final time (default 1)");
  solve->add_option("--N", f.N, "number of steps (default 100)");
  solve->add_option("--g0", flags->g0, "initial element: so3 9 numbers row-major, heisenberg a,b,c (default identity)");
  solve->add_option("--gT", flags->gT, "final element, as --g0");
  solve->add_option("--a0", flags->a0, "so3: initial direction; gT = minimal rotation taking a0 to aT");
  solve->add_option("--aT", flags->aT, "so3: final direction");
  solve->add_option("--method", f.method,
                    "two-level | shooting | multiple-shooting | collocation (default shooting: augmented shooting "
                    "with analytic Jacobian, continued in T when needed; multiple-shooting: lifted LM over "
                    "--segments segments; collocation: fourth-order adaptive collocation)");
  solve->add_option("--continuation", f.continuation,
                    "shooting: T (default; continue in T from a shorter horizon when direct shooting fails) | "
                    "lambda (continue in lambda from the lambda = 0 solution) | none (direct shooting only)");
  solve->add_option("--segments", f.segments, "multiple-shooting only: number of segments (default about 100 steps each, at most 16)");
  solve->add_option("--order", f.order, "1 (the paper's scheme) | 2 (second order) (default 1)");
  solve->add_option("--tol", f.tol, "tolerance (default 1e-10)");
  solve->add_option("--samples", f.samples, "collocation only: output at this many uniform times on [0, T] (0: the final mesh)");
  solve->add_option("--max-iterations", f.max_iterations, "iteration limit of each loop (default 200)");
  solve->add_option("--output", f.output, "output file (default stdout)");
  return {solve, [solve, flags] { return run_solve(*solve, *flags); }};
}

}  // namespace cartan::cli
