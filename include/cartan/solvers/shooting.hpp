#pragma once
// What single shooting of every kernel shares (transported/shooting.hpp, general/shooting.hpp):
// the options its Levenberg–Marquardt solve takes from ShootingOptions.

#include "cartan/numerics/nonlinear_solve.hpp"
#include "cartan/principle/options.hpp"

namespace cartan::solvers {

/// Levenberg–Marquardt's options for a shooting's.
inline numerics::NonlinearSolveOptions solver_options(const ShootingOptions& options) {
  numerics::NonlinearSolveOptions lm;
  lm.tolerance = options.tolerance;
  lm.max_iterations = options.max_iterations;
  lm.no_progress_window = options.no_progress_window;
  lm.max_initial_residual = options.max_initial_residual;
  lm.monitor = options.monitor;
  lm.evaluations_stop = true;  // both kernels' sweeps poll the monitor
  return lm;
}

}  // namespace cartan::solvers
