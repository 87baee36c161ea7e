// Collocation's start on a mesh, every kernel's (solvers/collocation.hpp).
#include "cartan/solvers/collocation.hpp"

#include <utility>

namespace cartan::solvers {

MeshFirst collocate_from_mesh(const numerics::BvpSystem& system, const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                              const numerics::CollocationOptions& options, OnMeshFailure on_failure) {
  MeshFirst out{numerics::solve_collocation_on_mesh(system, t, y, Eigen::VectorXd(0), options), false};
  if (out.result.success()) {
    numerics::BvpResult refined = numerics::solve_collocation(system, out.result, options);
    refined.newton_iterations += out.result.newton_iterations;
    refined.jacobian_evaluations += out.result.jacobian_evaluations;
    out.result = std::move(refined);
    out.converged_on_mesh = true;
  } else if (on_failure == OnMeshFailure::Adaptive && out.result.status != Status::Interrupted) {
    out.result = numerics::solve_collocation(system, t, y, Eigen::VectorXd(0), options);
  }
  return out;
}

}  // namespace cartan::solvers
