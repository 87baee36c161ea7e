// Single shooting's bookkeeping, every kernel's (solvers/shooting.hpp).
#include "cartan/solvers/shooting.hpp"

#include "cartan/errors.hpp"
#include "cartan/numerics/nonlinear_solve.hpp"

namespace cartan::solvers {

namespace {

/// Levenberg–Marquardt's options for a shooting's.
numerics::NonlinearSolveOptions solver_options(const ShootingOptions& options) {
  numerics::NonlinearSolveOptions lm;
  lm.tolerance = options.tolerance;
  lm.max_iterations = options.max_iterations;
  lm.no_progress_window = options.no_progress_window;
  lm.max_initial_residual = options.max_initial_residual;
  lm.monitor = options.monitor;
  lm.evaluations_stop = true;  // both kernels' sweeps poll the monitor
  return lm;
}

}  // namespace

numerics::ShootingOutcome shoot(numerics::ShootingKernel& kernel, int velocity_size, double T, double aux_scale,
                                double aux_size, const ShootingOptions& options, const Eigen::VectorXd& y0,
                                const ShotLabel& label, ResultCore& result) {
  numerics::ShootingOutcome outcome =
      numerics::shoot(kernel,
                      {.velocity_size = velocity_size, .horizon = T, .aux_scale = aux_scale, .aux_size = aux_size,
                       .analytic_jacobian = options.analytic_jacobian, .solver = solver_options(options)},
                      y0);
  result.inner_iterations = outcome.report.iterations;
  result.residual_history = outcome.report.residual_history;
  result.sweeps = outcome.sweeps;
  result.status = outcome.status;
  result.message = std::string(label.method) + " (" +
                   std::string(options.analytic_jacobian ? label.jacobian : "finite-difference") + " Jacobian, " +
                   std::string(label.auxiliary) + " scale " + format_value(aux_scale) + label.extra +
                   "): " + outcome.summary();
  return outcome;
}

}  // namespace cartan::solvers
