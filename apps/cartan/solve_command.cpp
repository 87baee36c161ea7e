#include "solve_command.hpp"

#include "cartan/transported/compiled.hpp"
#include "connection_command.hpp"
#include "manifold_command.hpp"
#include "cartan/models/catalogue.hpp"
#include "solution_json.hpp"

namespace cartan::cli {

namespace {

constexpr std::string_view kSolveCommandWhere = "cartan solve";

template <groups::LieGroup G>
transported::SolveGuess<G> guess_of(const ProblemSpec& spec) {
  transported::SolveGuess<G> guess;
  if (!spec.v0.empty()) guess.v0 = groups::TangentOf<G>(spec.v0.data());
  if (!spec.xi0.empty()) guess.xi0 = groups::CovectorOf<G>(spec.xi0.data());
  return guess;
}

/// Throws std::invalid_argument ("cartan solve: g0 = ... is not ...") unless g0 and gT are
/// elements of the spec's group (models::ModelInfo::check_element).
void check_endpoints(const ProblemSpec& spec) {
  const models::ModelInfo& model = models::find_model(spec.group, spec.model, kSolveCommandWhere);
  model.check_element(spec.g0, kSolveCommandWhere, "g0");
  if (spec.a0.empty()) model.check_element(spec.gT, kSolveCommandWhere, "gT");
}

}  // namespace

transported::SolveOptions solve_options(const ProblemSpec& spec) {
  transported::SolveOptions options;
  options.method = parse_enum<transported::Method>(spec.method, "cartan solve");
  options.continuation = parse_enum<transported::Continuation>(spec.continuation, "cartan solve");
  options.order = spec.order == 2 ? transported::SchemeOrder::Second : transported::SchemeOrder::First;
  options.tol = spec.tol;
  options.max_iterations = spec.max_iterations;
  if (spec.time_limit > 0) options.time_limit = spec.time_limit;
  if (spec.segments > 0) options.segments = spec.segments;
  options.samples = spec.samples;
  return options;
}

SO3Endpoints so3_endpoints(const ProblemSpec& spec) {
  check_endpoints(spec);
  return {models::element_of<groups::SO3>(spec.g0), models::element_of<groups::SO3>(final_element(spec))};
}

nlohmann::json solve(const ProblemSpec& spec, const SolveMonitor& monitor) {
  if (is_manifold_problem(spec)) return solve_manifold(spec, monitor);
  if (is_general_connection(spec)) return solve_with_connection(spec, monitor);
  check_endpoints(spec);
  return models::visit_model(spec.group, spec.model, kSolveCommandWhere, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    const transported::TransportedProblem<G, typename Entry::Lagrangian> problem{
        models::make_lagrangian<Entry>(spec.inertia, kSolveCommandWhere), spec.lambda, spec.T, spec.N, models::element_of<G>(spec.g0),
        models::element_of<G>(final_element(spec))};
    transported::SolveOptions options = solve_options(spec);
    options.monitor = monitor;
    return solution_json(spec, transported::solve(problem, options, guess_of<G>(spec)));
  });
}

}  // namespace cartan::cli
