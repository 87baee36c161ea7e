#pragma once
// The paper's two-level scheme's driver (§7 "A two-level scheme"), compiled once
// (src/solvers/two_level.cpp): the outer fixed-point loop on the auxiliary sequence around an
// inner Levenberg–Marquardt shooting on v0, their statuses, counters and message. The sweeps are
// the kernel's typed arithmetic (methods/lie_group/two_level.hpp).

#include <Eigen/Core>
#include <optional>
#include <string>

#include "cartan/monitor.hpp"
#include "cartan/principle/result.hpp"

namespace cartan::solvers {

/// A kernel's fixed-point system as the driver sees it; `record` writes into the result the
/// driver was given.
class FixedPointSystem {
 public:
  virtual ~FixedPointSystem() = default;
  /// The inner residual at v0 with the current auxiliary sequence and, if jac is set (analytic
  /// Jacobians only), its Jacobian; false (failure() set) if the sweep failed.
  virtual bool inner(const Eigen::VectorXd& v0, Eigen::VectorXd& r, Eigen::MatrixXd* jac) = 0;
  /// Replaces the auxiliary sequence by the backward recursion of the rates of a sweep from v0
  /// (disc-aux); returns max_k |new - old| (componentwise), or nothing if the sweep failed
  /// (failure() set).
  virtual std::optional<double> update(const Eigen::VectorXd& v0) = 0;
  /// The trajectory of a sweep from v0 with the final sequence recorded in the result; false if it failed.
  virtual bool record(const Eigen::VectorXd& v0) = 0;
  virtual const std::string& failure() const = 0;
};

struct FixedPointOptions {
  double tolerance = 1e-8;         ///< on max_k |new - old|, in units of `auxiliary_scale`
  double auxiliary_scale = 1;
  double inner_tolerance = 1e-13;
  int max_outer = 100;
  int max_inner = 100;
  bool analytic_jacobian = false;  ///< else forward differences (step 1e-7) of the inner residual
  const SolveMonitor* monitor = nullptr;
};

/// The two-level iteration of `system` from `v0`: writes into `result` (the one `system`
/// records into) the counters, the outer changes as residual history, the status and the message.
void solve_fixed_point(FixedPointSystem& system, const FixedPointOptions& options, const Eigen::VectorXd& v0,
                       ResultCore& result);

}  // namespace cartan::solvers
