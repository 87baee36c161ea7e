#include "collocation_command.hpp"

#include "cartan/bvp/transported_solution.hpp"
#include "solution_json.hpp"

namespace cartan::cli {

namespace {

bvp::CollocationOptions collocation_options(const ProblemSpec& spec) {
  return {.tol = spec.tol, .max_nodes = bvp::kTransportedMaxNodes, .max_newton_iterations = spec.max_iterations};
}

/// The solution's JSON plus what only collocation reports: the final mesh size and the largest
/// relative RMS residual on it.
template <LieGroup G>
nlohmann::json collocation_json(const ProblemSpec& spec, const TransportedSolution<G>& s, const bvp::BvpResult& raw) {
  nlohmann::json out = solution_json(spec, s, bvp::kCollocationOrder);
  out["mesh_size"] = raw.t.size();
  out["max_residual"] = raw.max_rms_residual;
  return out;
}

template <Potential<SO3> V>
nlohmann::json solve_so3(const ProblemSpec& spec, const TransportedProblem<SO3, NaturalLagrangian<SO3, V>>& problem) {
  using Collocation = bvp::TransportedCollocation<SO3, V>;
  const bvp::CollocationFallback fallback = spec.continuation == "none"     ? bvp::CollocationFallback::None
                                            : spec.continuation == "lambda" ? bvp::CollocationFallback::ContinuationInLambda
                                                                            : bvp::CollocationFallback::ContinuationInT;
  bvp::BvpResult raw;
  const TransportedSolution<SO3> s =
      bvp::solve_transported_by_collocation(problem, collocation_options(spec), spec.samples, fallback, &raw);
  nlohmann::json out = collocation_json(spec, s, raw);
  out["group_defect"] = Collocation::orthogonality_defect(raw);
  return out;
}

}  // namespace

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<Heisenberg, H3Oscillator>& problem) {
  bvp::BvpResult raw;
  const TransportedSolution<Heisenberg> s =
      bvp::solve_heisenberg_transported(problem, collocation_options(spec), spec.samples, &raw);
  return collocation_json(spec, s, raw);
}

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<SO3, RigidBody>& problem) {
  return solve_so3(spec, problem);
}

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<SO3, SO3Oscillator>& problem) {
  return solve_so3(spec, problem);
}

}  // namespace cartan::cli
