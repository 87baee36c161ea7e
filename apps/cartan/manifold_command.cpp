#include "manifold_command.hpp"

#include "cartan/general/compiled.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "solution_json.hpp"
#include "solve_command.hpp"

namespace cartan::cli {

SphereProblem sphere_problem(const ProblemSpec& spec) {
  const Eigen::Vector3d q0(spec.q0.data()), qT(spec.qT.data());
  manifolds::Sphere::Frame frame;
  frame.col(0) = (qT - q0.dot(qT) * q0).normalized();  // along the minimal great circle (validate: not +-q0)
  frame.col(1) = q0.cross(Eigen::Vector3d(frame.col(0)));
  const SphereParticle particle = SphereParticle::with_linear_potential(Eigen::Vector2d(spec.mass[0], spec.mass[1]).asDiagonal(),
                                                                        Eigen::Vector3d(0, 0, spec.gravity));
  return {manifolds::Sphere{}, general::ErasedLagrangian<manifolds::Sphere>(particle), spec.T, spec.N, q0, qT, frame};
}

nlohmann::json solve_manifold(const ProblemSpec& spec, const SolveMonitor& monitor) {
  const SphereProblem problem = sphere_problem(spec);
  transported::SolveOptions options = solve_options(spec);
  options.monitor = monitor;
  general::GeneralGuess<manifolds::Sphere> guess;
  if (!spec.v0.empty()) guess.v0 = Eigen::Vector2d(spec.v0.data());
  const general::GeneralSolution<manifolds::Sphere> s = general::solve(problem, options, guess);
  nlohmann::json out = result_header(spec, std::string(to_string(s.status)), s.message, std::string(to_string(s.method)),
                                     s.order, s.branch);
  add_general_solution(out, s, "q");
  out["frame0"] = rows(std::vector<Eigen::Vector3d>{problem.frame0->col(0), problem.frame0->col(1)});  // the rows e1, e2
  return out;
}

}  // namespace cartan::cli
