#include "solve_command.hpp"

#include "cartan/models/heisenberg_oscillator.hpp"
#include "cartan/models/rigid_body.hpp"
#include "cartan/transported/solve.hpp"
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

template <LieGroup G>
SolveGuess<G> guess_of(const ProblemSpec& spec) {
  SolveGuess<G> guess;
  if (!spec.v0.empty()) guess.v0 = TangentOf<G>(spec.v0.data());
  if (!spec.xi0.empty()) guess.xi0 = CovectorOf<G>(spec.xi0.data());
  return guess;
}

template <LieGroup G, ReducedLagrangian<G> L>
nlohmann::json run(const ProblemSpec& spec, const TransportedProblem<G, L>& problem, const SolveMonitor& monitor) {
  SolveOptions options = solve_options(spec);
  options.monitor = monitor;
  return solution_json(spec, solve(problem, options, guess_of<G>(spec)));
}

}  // namespace

SolveOptions solve_options(const ProblemSpec& spec) {
  SolveOptions options;
  options.method = parse_enum<Method>(spec.method, "cartan solve");
  options.continuation = parse_enum<Continuation>(spec.continuation, "cartan solve");
  options.order = spec.order == 2 ? SchemeOrder::Second : SchemeOrder::First;
  options.tol = spec.tol;
  options.max_iterations = spec.max_iterations;
  if (spec.segments > 0) options.segments = spec.segments;
  options.samples = spec.samples;
  return options;
}

SO3Endpoints so3_endpoints(const ProblemSpec& spec) {
  SO3Endpoints ends{rotation(spec.g0, "g0"), {}};
  ends.gT = spec.a0.empty() ? rotation(spec.gT, "gT")
                            : SO3::minimal_rotation(Eigen::Vector3d(spec.a0.data()), Eigen::Vector3d(spec.aT.data()));
  return ends;
}

nlohmann::json solve(const ProblemSpec& spec, const SolveMonitor& monitor) {
  const Eigen::Vector3d inertia(spec.inertia[0], spec.inertia[1], spec.inertia[2]);
  if (spec.group == "heisenberg") {
    const Heisenberg::Element g0(spec.g0[0], spec.g0[1], spec.g0[2]);
    const Heisenberg::Element gT(spec.gT[0], spec.gT[1], spec.gT[2]);
    const TransportedProblem<Heisenberg, H3Oscillator> problem{H3Oscillator(inertia.asDiagonal().toDenseMatrix()),
                                                               spec.lambda, spec.T, spec.N, g0, gT};
    return run(spec, problem, monitor);
  }
  const auto [g0, gT] = so3_endpoints(spec);
  const Eigen::Matrix3d inertia_matrix = inertia.asDiagonal();
  if (spec.model == "oscillator") {
    return run(spec, TransportedProblem<SO3, SO3Oscillator>{SO3Oscillator(inertia_matrix), spec.lambda, spec.T, spec.N, g0, gT},
               monitor);
  }
  return run(spec, TransportedProblem<SO3, RigidBody>{RigidBody(inertia_matrix), spec.lambda, spec.T, spec.N, g0, gT},
             monitor);
}

}  // namespace cartan::cli
