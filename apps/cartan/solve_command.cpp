#include "solve_command.hpp"

#include "cartan/models/heisenberg_oscillator.hpp"
#include "cartan/models/rigid_body.hpp"
#include "cartan/transported/continuation.hpp"
#include "cartan/transported/multiple_shooting.hpp"
#include "cartan/transported/two_level.hpp"
#include "collocation_command.hpp"
#include "solution_json.hpp"

namespace cartan::cli {

namespace {

/// Input rotation matrices are accepted within this tolerance and projected onto SO(3), so that
/// matrices printed with 7 or more digits can be passed back in.
constexpr double kRotationInputTolerance = 1e-6;

SO3::Element rotation(const std::vector<double>& rowmajor, const std::string& name) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = rowmajor[static_cast<std::size_t>(i)];
  try {
    return SO3::from_matrix(m, kRotationInputTolerance);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()).replace(0, std::string("SO3: matrix").size(), "cartan solve: " + name));
  }
}

template <LieGroup G, ReducedLagrangian<G> L>
nlohmann::json run(const ProblemSpec& spec, const TransportedProblem<G, L>& problem) {
  const SchemeOrder order = spec.order == 2 ? SchemeOrder::Second : SchemeOrder::First;
  TransportedSolution<G> s;
  if (spec.method == "two-level") {
    s = solve_two_level(problem, {.order = order, .tolerance = spec.tol, .max_outer = spec.max_iterations,
                                  .max_inner = spec.max_iterations});
    s.branch = "direct from the geodesic guess";
  } else if (spec.method == "multiple-shooting") {
    MultipleShootingOptions options{.order = order, .tolerance = spec.tol, .max_iterations = spec.max_iterations};
    if (spec.segments > 0) options.segments = spec.segments;
    s = solve_multiple_shooting(problem, options);
  } else {
    const ContinuationOptions options{
        .shooting = {.order = order, .tolerance = spec.tol, .max_iterations = spec.max_iterations}};
    if (spec.continuation == "none") {
      s = solve_shooting(problem, options.shooting);
      s.branch = "direct from the geodesic guess";
    } else if (spec.continuation == "lambda") {
      s = solve_continuation_in_lambda(problem, 0.0, options);
    } else {
      s = solve_continuation_in_T(problem, options);
    }
    s.method = "shooting";
  }
  return solution_json(spec, s, spec.order);
}

}  // namespace

SO3Endpoints so3_endpoints(const ProblemSpec& spec) {
  SO3Endpoints ends{rotation(spec.g0, "g0"), {}};
  ends.gT = spec.a0.empty() ? rotation(spec.gT, "gT")
                            : SO3::minimal_rotation(Eigen::Vector3d(spec.a0.data()), Eigen::Vector3d(spec.aT.data()));
  return ends;
}

nlohmann::json solve(const ProblemSpec& spec) {
  const Eigen::Vector3d inertia(spec.inertia[0], spec.inertia[1], spec.inertia[2]);
  if (spec.group == "heisenberg") {
    const Heisenberg::Element g0(spec.g0[0], spec.g0[1], spec.g0[2]);
    const Heisenberg::Element gT(spec.gT[0], spec.gT[1], spec.gT[2]);
    const TransportedProblem<Heisenberg, H3Oscillator> problem{H3Oscillator(inertia.asDiagonal().toDenseMatrix()),
                                                               spec.lambda, spec.T, spec.N, g0, gT};
    if (spec.method == "collocation") return solve_by_collocation(spec, problem);
    return run(spec, problem);
  }
  const auto [g0, gT] = so3_endpoints(spec);
  const Eigen::Matrix3d inertia_matrix = inertia.asDiagonal();
  if (spec.model == "oscillator") {
    const TransportedProblem<SO3, SO3Oscillator> problem{SO3Oscillator(inertia_matrix), spec.lambda, spec.T, spec.N, g0, gT};
    return spec.method == "collocation" ? solve_by_collocation(spec, problem) : run(spec, problem);
  }
  const TransportedProblem<SO3, RigidBody> problem{RigidBody(inertia_matrix), spec.lambda, spec.T, spec.N, g0, gT};
  return spec.method == "collocation" ? solve_by_collocation(spec, problem) : run(spec, problem);
}

}  // namespace cartan::cli
