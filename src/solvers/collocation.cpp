// Collocation's driver, every kernel's (solvers/collocation.hpp).
#include "cartan/solvers/collocation.hpp"

#include <optional>
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

namespace {

/// A start solved as the kernel solves one (ContinuousProblem::starts_on_mesh).
numerics::BvpResult solve_from(const ContinuousProblem& problem, const numerics::BvpSystem& system,
                               const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                               const numerics::CollocationOptions& options) {
  if (problem.starts_on_mesh()) return collocate_from_mesh(system, t, y, options, OnMeshFailure::Adaptive).result;
  return numerics::solve_collocation(system, t, y, Eigen::VectorXd(0), options);
}

/// The fallback's order-2 shooting solution (collocate's comment), at collocation's tolerance
/// and Newton limit, reporting to collocation's monitor. Its sweeps count those of a failed
/// first attempt, which continuation in T takes over without counting.
PathResultPtr order_two_shooting(StrategyKernel& discrete, Continuation fallback,
                                 const numerics::CollocationOptions& options, int& sweeps) {
  const ContinuationOptions path{.shooting = {.order = SchemeOrder::Second, .tolerance = options.tol,
                                              .max_iterations = options.max_newton_iterations,
                                              .monitor = options.monitor}};
  if (fallback == Continuation::Lambda) {
    PathResultPtr r = discrete.continue_in_lambda(path, 0.0);
    sweeps = r->core().sweeps;
    return r;
  }
  ShootingOptions first = path.shooting;
  first.no_progress_window = discrete.first_shooting_window();
  const std::optional<SolveMonitor> named = SolveMonitor::staged(options.monitor, "shooting");
  if (named) first.monitor = &*named;
  PathResultPtr direct = discrete.shoot(first);
  direct->core().branch = direct_branch(discrete);
  sweeps = direct->core().sweeps;
  if (direct->core().converged() || direct->core().status == Status::Interrupted) return direct;
  PathResultPtr r = discrete.continue_in_T(path, std::move(direct));
  sweeps += r->core().sweeps;
  return r;
}

}  // namespace

Collocated collocate(const ContinuousProblem& problem, StrategyKernel& discrete, Continuation fallback,
                     const numerics::CollocationOptions& options) {
  const numerics::BvpSystem system = problem.system();
  Eigen::VectorXd t;
  Eigen::MatrixXd y;
  const bool given = problem.start(t, y);
  Collocated out;
  out.branch = given ? "from the given trajectory" : "direct from the geodesic guess on a uniform mesh of N intervals";
  if (fallback == Continuation::None) {
    out.result = solve_from(problem, system, t, y, options);
    return out;
  }
  MeshFirst on_mesh = collocate_from_mesh(system, t, y, options, OnMeshFailure::Report);
  out.result = std::move(on_mesh.result);
  if (on_mesh.converged_on_mesh || out.result.status == Status::Interrupted) return out;

  PathResultPtr shooting = order_two_shooting(discrete, fallback, options, out.shooting_sweeps);
  if (!shooting->core().converged()) {
    out.result.status = shooting->core().status;
    out.result.message += "; the order-2 shooting fallback failed too: " + shooting->core().message;
    out.branch = "failed: " + out.branch + ", then the order-2 shooting fallback";
    return out;
  }
  const numerics::BvpResult failed_on_mesh = std::move(out.result);
  std::string path = "from the order-2 shooting solution (";
  path += shooting->core().branch;
  path += ") after Newton ";
  path += given ? "from the given trajectory failed on its mesh" : "from the geodesic guess failed on the N-interval mesh";
  problem.start_from(std::move(shooting), t, y);
  out.result = solve_from(problem, system, t, y, options);
  out.result.newton_iterations += failed_on_mesh.newton_iterations;
  out.result.jacobian_evaluations += failed_on_mesh.jacobian_evaluations;
  out.branch = std::move(path);
  return out;
}

}  // namespace cartan::solvers
