#include "manifold_command.hpp"

#include "cartan/general/solve.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "solution_json.hpp"
#include "solve_command.hpp"

namespace cartan::cli {

namespace {

using Sphere = manifolds::Sphere;
using Particle = general::KineticPotential<Sphere>;

/// Rows of the entries of fixed-size Eigen objects, row-major.
template <class Value>
nlohmann::json row_major_rows(const std::vector<Value>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& x : values) {
    const Eigen::Matrix<double, Value::ColsAtCompileTime, Value::RowsAtCompileTime> transposed = x.transpose();
    out.push_back(std::vector<double>(transposed.data(), transposed.data() + transposed.size()));
  }
  return out;
}

}  // namespace

nlohmann::json solve_manifold(const ProblemSpec& spec, const SolveMonitor& monitor) {
  const Eigen::Vector3d q0(spec.q0.data()), qT(spec.qT.data());
  Sphere::Frame frame;
  frame.col(0) = (qT - q0.dot(qT) * q0).normalized();  // along the minimal great circle (validate: not +-q0)
  frame.col(1) = q0.cross(Eigen::Vector3d(frame.col(0)));
  const Particle particle =
      Particle::with_linear_potential(Eigen::Vector2d(spec.mass[0], spec.mass[1]).asDiagonal(), Eigen::Vector3d(0, 0, spec.gravity));
  const general::GeneralProblem<Sphere, Particle> problem{Sphere{}, particle, spec.T, spec.N, q0, qT, frame};
  transported::SolveOptions options = solve_options(spec);
  options.monitor = monitor;
  general::GeneralGuess<Sphere> guess;
  if (!spec.v0.empty()) guess.v0 = Eigen::Vector2d(spec.v0.data());
  const general::GeneralSolution<Sphere> s = general::solve(problem, options, guess);
  const auto& tr = s.trajectory;
  nlohmann::json out = result_header(spec, std::string(to_string(s.status)), s.message, std::string(to_string(s.method)),
                                     s.order, s.branch);
  out["t"] = tr.t;
  out["q"] = row_major_rows(tr.q);
  out["v"] = row_major_rows(tr.v);
  out["mu"] = row_major_rows(tr.mu);
  out["Xi"] = row_major_rows(tr.Xi);
  out["frame0"] = row_major_rows(std::vector<Eigen::Vector3d>{frame.col(0), frame.col(1)});  // the rows e1, e2
  out["terminal_error"] = s.terminal_error;
  out["xi_terminal"] = s.xi_terminal;
  out["iterations"] = {{"outer", 0}, {"inner", s.iterations}, {"sweeps", s.sweeps}};
  out["solve_time_s"] = s.solve_time_s;
  return out;
}

}  // namespace cartan::cli
