#include "solve_command.hpp"

#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/transported/solve.hpp"
#include "solution_json.hpp"

namespace cartan::cli {

namespace {

/// Input rotation matrices are accepted within this tolerance and projected onto SO(3), so that
/// matrices printed with 7 or more digits can be passed back in.
constexpr double kRotationInputTolerance = 1e-6;

groups::SO3::Element rotation(const std::vector<double>& rowmajor, const std::string& name) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = rowmajor[static_cast<std::size_t>(i)];
  try {
    return groups::SO3::from_matrix(m, kRotationInputTolerance);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()).replace(0, std::string("SO3: matrix").size(), "cartan solve: " + name));
  }
}

template <groups::LieGroup G>
transported::SolveGuess<G> guess_of(const ProblemSpec& spec) {
  transported::SolveGuess<G> guess;
  if (!spec.v0.empty()) guess.v0 = groups::TangentOf<G>(spec.v0.data());
  if (!spec.xi0.empty()) guess.xi0 = groups::CovectorOf<G>(spec.xi0.data());
  return guess;
}

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
nlohmann::json run(const ProblemSpec& spec, const transported::TransportedProblem<G, L>& problem, const SolveMonitor& monitor) {
  transported::SolveOptions options = solve_options(spec);
  options.monitor = monitor;
  return solution_json(spec, transported::solve(problem, options, guess_of<G>(spec)));
}

}  // namespace

transported::SolveOptions solve_options(const ProblemSpec& spec) {
  transported::SolveOptions options;
  options.method = parse_enum<transported::Method>(spec.method, "cartan solve");
  options.continuation = parse_enum<transported::Continuation>(spec.continuation, "cartan solve");
  options.order = spec.order == 2 ? transported::SchemeOrder::Second : transported::SchemeOrder::First;
  options.tol = spec.tol;
  options.max_iterations = spec.max_iterations;
  if (spec.segments > 0) options.segments = spec.segments;
  options.samples = spec.samples;
  return options;
}

SO3Endpoints so3_endpoints(const ProblemSpec& spec) {
  SO3Endpoints ends{rotation(spec.g0, "g0"), {}};
  ends.gT = spec.a0.empty() ? rotation(spec.gT, "gT")
                            : groups::SO3::minimal_rotation(Eigen::Vector3d(spec.a0.data()), Eigen::Vector3d(spec.aT.data()));
  return ends;
}

nlohmann::json solve(const ProblemSpec& spec, const SolveMonitor& monitor) {
  const Eigen::Vector3d inertia(spec.inertia[0], spec.inertia[1], spec.inertia[2]);
  if (spec.group == "heisenberg") {
    const groups::Heisenberg::Element g0(spec.g0[0], spec.g0[1], spec.g0[2]);
    const groups::Heisenberg::Element gT(spec.gT[0], spec.gT[1], spec.gT[2]);
    const transported::TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator> problem{mechanics::H3Oscillator(inertia.asDiagonal().toDenseMatrix()),
                                                               spec.lambda, spec.T, spec.N, g0, gT};
    return run(spec, problem, monitor);
  }
  const auto [g0, gT] = so3_endpoints(spec);
  const Eigen::Matrix3d inertia_matrix = inertia.asDiagonal();
  if (spec.model == "oscillator") {
    return run(spec, transported::TransportedProblem<groups::SO3, mechanics::SO3Oscillator>{mechanics::SO3Oscillator(inertia_matrix), spec.lambda, spec.T, spec.N, g0, gT},
               monitor);
  }
  return run(spec, transported::TransportedProblem<groups::SO3, mechanics::RigidBody>{mechanics::RigidBody(inertia_matrix), spec.lambda, spec.T, spec.N, g0, gT},
             monitor);
}

}  // namespace cartan::cli
