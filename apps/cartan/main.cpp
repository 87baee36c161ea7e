// The cartan command-line tool. `cartan solve --help` lists the options; exit codes:
// 0 converged, 1 the solver failed (the JSON result is still written), 2 bad input.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>

#include "problem_spec.hpp"
#include "solve_command.hpp"

namespace {

constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;

int run_solve(cartan::cli::ProblemSpec spec, const std::string& problem_file, const std::vector<std::string>& set_flags,
              const cartan::cli::ProblemSpec& from_flags) {
  using cartan::cli::ProblemSpec;
  if (!problem_file.empty()) {
    std::ifstream in(problem_file);
    if (!in) throw std::invalid_argument("cartan solve: --problem = " + problem_file + " cannot be opened");
    nlohmann::json file;
    try {
      file = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
      throw std::invalid_argument("cartan solve: --problem = " + problem_file + " is not valid JSON: " + e.what());
    }
    cartan::cli::apply_json(spec, file);
  }
  // Flags override the file.
  for (const auto& flag : set_flags) {
    if (flag == "group") spec.group = from_flags.group;
    if (flag == "model") spec.model = from_flags.model;
    if (flag == "inertia") spec.inertia = from_flags.inertia;
    if (flag == "lambda") spec.lambda = from_flags.lambda;
    if (flag == "T") spec.T = from_flags.T;
    if (flag == "N") spec.N = from_flags.N;
    if (flag == "g0") spec.g0 = from_flags.g0;
    if (flag == "gT") spec.gT = from_flags.gT;
    if (flag == "a0") spec.a0 = from_flags.a0;
    if (flag == "aT") spec.aT = from_flags.aT;
    if (flag == "method") spec.method = from_flags.method;
    if (flag == "order") spec.order = from_flags.order;
    if (flag == "tol") spec.tol = from_flags.tol;
    if (flag == "samples") spec.samples = from_flags.samples;
    if (flag == "segments") spec.segments = from_flags.segments;
    if (flag == "continuation") spec.continuation = from_flags.continuation;
    if (flag == "max-iterations") spec.max_iterations = from_flags.max_iterations;
    if (flag == "output") spec.output = from_flags.output;
  }
  cartan::cli::validate(spec);
  const nlohmann::json result = cartan::cli::solve(spec);
  if (spec.output.empty()) {
    std::cout << result.dump() << '\n';
  } else {
    std::ofstream out(spec.output);
    if (!out) throw std::invalid_argument("cartan solve: --output = " + spec.output + " cannot be written");
    out << result.dump() << '\n';
  }
  return result["status"] == "converged" ? 0 : kExitFailed;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cartan: geometric mechanics on Lie groups with invariant connections"};
  app.require_subcommand(1);
  auto* solve = app.add_subcommand("solve", "Solve the transported-velocity boundary-value problem (paper eq:reduced-system)");
  solve->footer(
      "Examples:\n"
      "  cartan solve --model free-rigid-body --lambda 0.5 --T 50 --N 1000 --a0 -1,-1,-1 --aT 0.9,1,1 --tol 1e-8\n"
      "  cartan solve --model oscillator --lambda 0 --T 12 --N 800 --a0=-0.7,-1,-0.7 --aT 0.8,0.8,1 --tol 1e-6\n"
      "  cartan solve --group heisenberg --model oscillator --lambda 0.5 --T 1 --N 200 --gT 1,0.5,0.8\n"
      "  cartan solve --problem problem.json --output result.json\n"
      "Exit codes: 0 converged, 1 solver failed (JSON still written), 2 bad input.");
  cartan::cli::ProblemSpec flags;
  std::string problem_file, inertia, g0, gT, a0, aT;
  solve->add_option("--problem", problem_file, "JSON problem file (keys as the flags; flags override it)");
  solve->add_option("--group", flags.group, "so3 | heisenberg (default so3)");
  solve->add_option("--model", flags.model, "free-rigid-body | oscillator (default free-rigid-body)");
  solve->add_option("--inertia", inertia, "I1,I2,I3 (default 2,3,4 for so3, 1,1,1 for heisenberg)");
  solve->add_option("--lambda", flags.lambda, "Cartan-Schouten parameter (any real; default 0.5)");
  solve->add_option("--T", flags.T, "final time (default 1)");
  solve->add_option("--N", flags.N, "number of steps (default 100)");
  solve->add_option("--g0", g0, "initial element: so3 9 numbers row-major, heisenberg a,b,c (default identity)");
  solve->add_option("--gT", gT, "final element, as --g0");
  solve->add_option("--a0", a0, "so3: initial direction; gT = minimal rotation taking a0 to aT");
  solve->add_option("--aT", aT, "so3: final direction");
  solve->add_option("--method", flags.method,
                    "two-level | shooting | multiple-shooting | collocation (default shooting: augmented shooting "
                    "with analytic Jacobian, continued in T when needed; multiple-shooting: lifted LM over "
                    "--segments segments; collocation: fourth-order adaptive collocation, heisenberg only)");
  solve->add_option("--continuation", flags.continuation,
                    "shooting: T (default; continue in T from a shorter horizon when direct shooting fails) | "
                    "lambda (continue in lambda from the lambda = 0 solution) | none (direct shooting only)");
  solve->add_option("--segments", flags.segments, "multiple-shooting: number of segments (default about 100 steps each, at most 16)");
  solve->add_option("--order", flags.order, "1 (the paper's scheme) | 2 (second order) (default 1)");
  solve->add_option("--tol", flags.tol, "tolerance (default 1e-10)");
  solve->add_option("--samples", flags.samples, "collocation: output at this many uniform times on [0, T] (0: the final mesh); unused by the shooting methods");
  solve->add_option("--max-iterations", flags.max_iterations, "iteration limit of each loop (default 200)");
  solve->add_option("--output", flags.output, "output file (default stdout)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "cartan: " << e.what() << " (see cartan " << (solve->parsed() ? "solve " : "") << "--help)\n";
    return kExitBadInput;
  }
  try {
    std::vector<std::string> set;
    for (const auto* opt : solve->get_options()) {
      if (opt->count() > 0) set.push_back(opt->get_name().substr(2));
    }
    if (!inertia.empty()) flags.inertia = cartan::cli::parse_list(inertia, "inertia");
    if (!g0.empty()) flags.g0 = cartan::cli::parse_list(g0, "g0");
    if (!gT.empty()) flags.gT = cartan::cli::parse_list(gT, "gT");
    if (!a0.empty()) flags.a0 = cartan::cli::parse_list(a0, "a0");
    if (!aT.empty()) flags.aT = cartan::cli::parse_list(aT, "aT");
    return run_solve(cartan::cli::ProblemSpec{}, problem_file, set, flags);
  } catch (const std::invalid_argument& e) {
    std::cerr << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cartan: internal error: " << e.what() << '\n';
    return kExitFailed;
  }
}
