#pragma once
// Multiple shooting's driver, compiled once (src/solvers/multiple_shooting.cpp): rounds of
// Levenberg–Marquardt on a kernel's lifted system with the charts re-centred between them, the
// tightening of the lifted tolerance until one plain sweep meets the requested one, the status
// and the message. The lifted system (unknowns, residual, analytic Jacobian) is the kernel's
// typed arithmetic (methods/lie_group/multiple_shooting.hpp).

#include <Eigen/Core>
#include <optional>
#include <string>

#include "cartan/monitor.hpp"
#include "cartan/principle/result.hpp"

namespace cartan::solvers {

/// A kernel's lifted system as the driver sees it; `record` writes into the result the driver
/// was given.
class LiftedSystem {
 public:
  virtual ~LiftedSystem() = default;
  /// The lifted unknowns of one sweep from the guess (the segments' references); empty if that
  /// sweep failed (failure() says why).
  virtual std::optional<Eigen::VectorXd> initialise() = 0;
  /// Moves the chart coordinates of x into the references.
  virtual void recentre(Eigen::VectorXd& x) = 0;
  /// The residual at x and, if jac is set, its Jacobian; false (failure() set) if a segment failed.
  virtual bool evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) = 0;
  /// The scaled terminal residual of one plain sweep from x's initial unknowns, or infinity.
  virtual double single_sweep_residual(const Eigen::VectorXd& x) = 0;
  /// One sweep from x's initial unknowns recorded in the result (trajectory, initial unknowns,
  /// terminal figures); false if it failed.
  virtual bool record(const Eigen::VectorXd& x) = 0;
  /// The unit of the terminal auxiliary (xi_scale).
  virtual double auxiliary_scale() const = 0;
  virtual const std::string& failure() const = 0;
};

struct LiftedOptions {
  int segments = 1;
  double tolerance = 1e-10;
  int max_iterations = 100;
  int recentre_every = 10;
  const SolveMonitor* monitor = nullptr;
};

/// Multiple shooting of `system` (methods/lie_group/multiple_shooting.hpp, solve_multiple_shooting):
/// writes into `result` (the one `system` records into) the counters, the residual history, the
/// status and the message, which begins with `header`.
void solve_lifted(LiftedSystem& system, const LiftedOptions& options, const std::string& header, ResultCore& result);

}  // namespace cartan::solvers
