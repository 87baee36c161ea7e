#pragma once
// Collocation of the continuous transported-velocity problem, every kernel's (the Lie-group
// kernel's methods/lie_group/collocation_solution.hpp, the general methods/manifold/collocation.hpp), compiled
// once (src/solvers/collocation.cpp): where it starts, the start on a mesh then refinement, the
// order-2 shooting fallback, the words of the path, and where a result is sampled. A kernel
// gives its continuous system and starts (ContinuousProblem: its arithmetic) and reads the
// result into its solution.

#include <Eigen/Core>
#include <string>

#include "cartan/numerics/collocation.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/solvers/strategy.hpp"

namespace cartan::solvers {

/// What collocation does when Newton fails on its start's mesh (docs/design/one-core.md D14).
enum class OnMeshFailure {
  Report,    ///< return that failure (for a caller that falls back to another start)
  Adaptive,  ///< run the adaptive solver from the same start (not after a stop)
};

struct MeshFirst {
  numerics::BvpResult result;
  bool converged_on_mesh = false;  ///< Newton converged on the start's mesh (then `result` is its refinement)
};

/// Newton on the start's mesh (t, y) first, then the adaptive refinement of its solution (the
/// Newton iterations and Jacobian evaluations of both summed): from a poor start the adaptive
/// solver alone refines a diverged iterate up to max_nodes (bench/README.md, "collocation
/// fallback"). When Newton fails on the mesh, `on_failure` says what follows.
MeshFirst collocate_from_mesh(const numerics::BvpSystem& system, const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                              const numerics::CollocationOptions& options, OnMeshFailure on_failure);

/// A kernel's continuous problem as the collocation driver sees it (docs/design/one-core.md D17:
/// the system and its starts are the kernel's arithmetic).
class ContinuousProblem {
 public:
  virtual ~ContinuousProblem() = default;
  virtual numerics::BvpSystem system() const = 0;
  /// The start: the given trajectory (returns true) or the geodesic guess on the problem's N
  /// intervals (false).
  virtual bool start(Eigen::VectorXd& t, Eigen::MatrixXd& y) const = 0;
  /// The start from `shooting`, a converged result of the kernel's discrete scheme.
  virtual void start_from(PathResultPtr shooting, Eigen::VectorXd& t, Eigen::MatrixXd& y) const = 0;
  /// How a start is solved: Newton on its mesh first, then the adaptive solver on failure
  /// (OnMeshFailure::Adaptive), or the adaptive solver alone (the Lie-group kernel's natural
  /// system, whose counters the paper's cases record: open decision O2 of one-core.md).
  virtual bool starts_on_mesh() const = 0;
};

/// What collocate() found: the collocation result (counters summed over every run) and the path
/// to it.
struct Collocated {
  numerics::BvpResult result;
  /// "direct from the geodesic guess on a uniform mesh of N intervals", "from the given
  /// trajectory", "from the order-2 shooting solution (...) after Newton from ... failed on ...",
  /// or "failed: ..." when the fallback failed too.
  std::string branch;
  int shooting_sweeps = 0;  ///< the order-2 shooting fallback's sweeps (0 when it did not run)
};

/// Collocation of `problem` from its start. With a `fallback` (Continuation::T, or Lambda where
/// `discrete` continues in lambda), Newton must converge on the start's mesh; when it does not,
/// the start is the order-2 shooting solution of the discrete problem (`discrete`'s scheme):
/// shooting from its guess within its first window, then continuation in T from that attempt; or
/// continuation in lambda from lambda = 0. Otherwise the adaptive solver would refine a start
/// outside Newton's basin up to max_nodes (bench/README.md, "collocation fallback") before the
/// fallback could begin. When the fallback fails too, the result is collocation's failure on the
/// mesh with the fallback's status (ContinuationFailed or Interrupted) and both messages.
Collocated collocate(const ContinuousProblem& problem, StrategyKernel& discrete, Continuation fallback,
                     const numerics::CollocationOptions& options);

/// Output times: the final mesh (samples == 0) or `samples` uniform times on [0, T].
inline Eigen::VectorXd output_times(const numerics::BvpResult& result, int samples, double T) {
  return samples == 0 ? result.t : Eigen::VectorXd::LinSpaced(samples, 0, T);
}

}  // namespace cartan::solvers
