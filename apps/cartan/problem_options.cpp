#include "problem_options.hpp"

#include <vector>

#include "cartan/transported/method.hpp"
#include "json_io.hpp"

namespace cartan::cli {

namespace {

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
    if (flag == "v0") spec.v0 = flags.v0;
    if (flag == "xi0") spec.xi0 = flags.xi0;
    if (flag == "max-iterations") spec.max_iterations = flags.max_iterations;
    if (flag == "output") spec.output = flags.output;
  }
}

}  // namespace

void add_problem_options(CLI::App& command, ProblemFlags& flags) {
  ProblemSpec& f = flags.spec;
  command.add_option("--problem", flags.problem_file, "JSON problem file (keys as the flags; flags override it)");
  command.add_option("--group", f.group, "so3 | heisenberg (default so3)");
  command.add_option("--model", f.model, "free-rigid-body | oscillator (default free-rigid-body)");
  command.add_option("--inertia", flags.inertia, "I1,I2,I3 (default 2,3,4 for so3, 1,1,1 for heisenberg)");
  command.add_option("--lambda", f.lambda, "Cartan-Schouten parameter (any real; default 0.5)");
  command.add_option("--T", f.T, "final time (default 1)");
  command.add_option("--N", f.N, "number of steps (default 100)");
  command.add_option("--g0", flags.g0, "initial element: so3 9 numbers row-major, heisenberg a,b,c (default identity)");
  command.add_option("--gT", flags.gT, "final element, as --g0");
  command.add_option("--a0", flags.a0, "so3: initial direction; gT = minimal rotation taking a0 to aT");
  command.add_option("--aT", flags.aT, "so3: final direction");
  command.add_option("--method", f.method,
                     enum_choices<transported::Method>() +
                         " (default auto: a strategy that tries shooting, continuation in T and in lambda, "
                         "collocation and multiple shooting in turn and stops at the first success; shooting: "
                         "augmented shooting with an analytic Jacobian; multiple-shooting: lifted LM over --segments "
                         "segments; two-level: the paper's scheme; collocation: fourth-order adaptive collocation)");
  command.add_option("--continuation", f.continuation,
                     enum_choices<transported::Continuation>() +
                         " (default none). shooting: how to reach a problem that fails from the guess (T: from a "
                         "shorter horizon; lambda: from the lambda = 0 solution); so3 collocation: where to start "
                         "when Newton from the geodesic guess fails (from that order-2 shooting solution)");
  command.add_option("--v0", flags.v0, "guess of v(0), 3 numbers (shooting methods; default the geodesic velocity)");
  command.add_option("--xi0", flags.xi0, "guess of xi(0), 3 numbers (shooting, multiple-shooting; default 0)");
  command.add_option("--segments", f.segments, "multiple-shooting only: number of segments (default about 100 steps each, at most 16)");
  command.add_option("--order", f.order, "1 (the paper's scheme) | 2 (second order) (default 1)");
  command.add_option("--tol", f.tol, "tolerance (default 1e-10)");
  command.add_option("--samples", f.samples, "collocation only: output at this many uniform times on [0, T] (0: the final mesh)");
  command.add_option("--max-iterations", f.max_iterations, "iteration limit of each loop (default 200)");
}

ProblemSpec problem_from(const CLI::App& command, ProblemFlags& flags) {
  std::vector<std::string> given;
  for (const auto* opt : command.get_options()) {
    if (opt->count() > 0) given.push_back(opt->get_name().substr(2));
  }
  if (!flags.inertia.empty()) flags.spec.inertia = parse_list(flags.inertia, "inertia");
  if (!flags.g0.empty()) flags.spec.g0 = parse_list(flags.g0, "g0");
  if (!flags.gT.empty()) flags.spec.gT = parse_list(flags.gT, "gT");
  if (!flags.a0.empty()) flags.spec.a0 = parse_list(flags.a0, "a0");
  if (!flags.aT.empty()) flags.spec.aT = parse_list(flags.aT, "aT");
  if (!flags.v0.empty()) flags.spec.v0 = parse_list(flags.v0, "v0");
  if (!flags.xi0.empty()) flags.spec.xi0 = parse_list(flags.xi0, "xi0");

  ProblemSpec spec;
  if (!flags.problem_file.empty()) {
    apply_json(spec, read_json_file(flags.problem_file, "cartan " + command.get_name() + ": --problem"));
  }
  override_with_flags(spec, flags.spec, given);  // flags override the file
  return spec;
}

}  // namespace cartan::cli
