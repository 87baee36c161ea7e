#pragma once
// The variational method's Newton iteration, compiled once (src/solvers/variational.cpp): a
// Newton step on the gradient of S_h at the interior nodes, damped by the natural monotonicity
// test (Deuflhard), until the simplified correction is below the tolerance. A stop ends an
// iteration where it is: the Hessian, its LU (numerics/dense_lu.hpp above a thousand unknowns)
// and each damping trial poll the monitor. The path, its gradient and Hessian are the kernel's
// typed arithmetic (methods/lie_group/variational.hpp).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cartan/monitor.hpp"
#include "cartan/status.hpp"

namespace cartan::solvers {

/// A kernel's path of nodes as the Newton iteration sees it: a current path and a trial.
class PathSystem {
 public:
  virtual ~PathSystem() = default;
  virtual Eigen::Index unknowns() const = 0;
  /// The gradient at the current path; false when it is not finite.
  virtual bool gradient(Eigen::VectorXd& out) = 0;
  /// The Hessian at the current path, whose gradient is `gradient`; false when not finite, or
  /// when the monitor polled a stop while forming it (SolveMonitor::poll; the iteration then ends
  /// as interrupted).
  virtual bool hessian(const Eigen::VectorXd& gradient, Eigen::MatrixXd& out) = 0;
  /// The gradient at the current path moved by s delta (the trial, kept until the next one);
  /// false when it is not finite.
  virtual bool trial(const Eigen::VectorXd& delta, double s, Eigen::VectorXd& gradient) = 0;
  /// The last trial becomes the current path.
  virtual void accept() = 0;
};

struct PathNewtonOptions {
  double tolerance = 1e-10;  ///< on max_j |delta_j| of the simplified correction
  int max_iterations = 50;
  const SolveMonitor* monitor = nullptr;
};

struct PathNewtonOutcome {
  Status status = Status::MaxIterations;
  int iterations = 0;
  std::string why;  ///< what stopped it, when not converged by the test (may be empty)
};

/// Newton on `system` (header comment); the simplified corrections' max norms are appended to
/// `history`.
PathNewtonOutcome newton_on_path(PathSystem& system, const PathNewtonOptions& options, std::vector<double>& history);

}  // namespace cartan::solvers
