#pragma once
// What collocation of every kernel shares (transported/collocation_solution.hpp,
// general/collocation.hpp): the start on a mesh, then refinement (compiled once,
// src/solvers/collocation.cpp), and where a result is sampled.

#include <Eigen/Core>

#include "cartan/numerics/collocation.hpp"
#include "cartan/principle/options.hpp"

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

/// Output times: the final mesh (samples == 0) or `samples` uniform times on [0, T].
inline Eigen::VectorXd output_times(const numerics::BvpResult& result, int samples, double T) {
  return samples == 0 ? result.t : Eigen::VectorXd::LinSpaced(samples, 0, T);
}

}  // namespace cartan::solvers
