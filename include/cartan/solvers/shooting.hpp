#pragma once
// Single shooting of every kernel (methods/lie_group/shooting.hpp, methods/manifold/shooting.hpp), compiled once
// (src/solvers/shooting.cpp): the kernel's sweeps are a numerics::ShootingKernel, the driver
// (numerics/shooting_driver.hpp) scales and solves, and this layer turns the outcome into a
// result's counters, status and words. What a kernel adds is its own (the general kernel's rule
// that a sweep ending away from qT is not converged).

#include <Eigen/Core>
#include <string>
#include <string_view>

#include "cartan/numerics/shooting_driver.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/result.hpp"

namespace cartan::solvers {

/// How a shooting's message names it: "<method> (<jacobian> Jacobian, <auxiliary> scale
/// s<extra>): <the driver's summary>", the Jacobian "finite-difference" when not analytic.
struct ShotLabel {
  std::string_view method;     ///< "shooting", "general shooting"
  std::string_view jacobian;   ///< the analytic Jacobian's name: "analytic", "tangent-linear"
  std::string_view auxiliary;  ///< "xi", "Xi"
  std::string extra;           ///< said inside the parentheses after the scale (may be empty)
};

/// Shoots `kernel` from y0 (the problem's units: velocity_size velocity components, then the
/// auxiliary's) at horizon T, the auxiliary in units of aux_scale, with the options'
/// Levenberg–Marquardt solve; writes into `result` the counters (inner iterations, residual
/// history, sweeps), the status and the message. Returns the driver's outcome.
numerics::ShootingOutcome shoot(numerics::ShootingKernel& kernel, int velocity_size, double T, double aux_scale,
                                double aux_size, const ShootingOptions& options, const Eigen::VectorXd& y0,
                                const ShotLabel& label, ResultCore& result);

}  // namespace cartan::solvers
