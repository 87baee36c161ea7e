#pragma once
// The general problem's results and guesses: its nodes, its discrete trajectory, the solution a
// solver returns, a guess, and the shooting's options. What a unit that calls the compiled solve
// (kernels/manifold/compiled.hpp) or reads its result needs, without the solvers.

#include <optional>
#include <string>
#include <vector>

#include "cartan/manifolds/manifold.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/result.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/scheme_order.hpp"
#include "cartan/status.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M>
struct GeneralNode {
  double t = 0;
  manifolds::PointOf<M> q;
  manifolds::FrameOf<M> frame;
  manifolds::ComponentsOf<M> mu;
  manifolds::ComponentMatrixOf<M> Xi;
  manifolds::ComponentsOf<M> v;
};

/// Every node k = 0..N of a discrete solution.
template <manifolds::ManifoldWithConnection M>
struct GeneralTrajectory {
  std::vector<double> t;
  std::vector<manifolds::PointOf<M>> q;
  std::vector<manifolds::FrameOf<M>> frame;
  std::vector<manifolds::ComponentsOf<M>> v, mu;
  std::vector<manifolds::ComponentMatrixOf<M>> Xi;

  void push(const GeneralNode<M>& node) {
    t.push_back(node.t), q.push_back(node.q), frame.push_back(node.frame), v.push_back(node.v);
    mu.push_back(node.mu), Xi.push_back(node.Xi);
  }
  /// Empties the trajectory and keeps its storage (a sweep that records reuses it).
  void clear() { t.clear(), q.clear(), frame.clear(), v.clear(), mu.clear(), Xi.clear(); }
  /// The last node.
  GeneralNode<M> back() const { return {t.back(), q.back(), frame.back(), mu.back(), Xi.back(), v.back()}; }
};

/// The general kernel's result (ResultCore, principle/result.hpp): its trajectory and unknowns.
/// Its action is NaN (the general kernel computes none); inner_iterations are
/// Levenberg–Marquardt's (summed along a continuation path) or collocation's Newton's.
template <manifolds::ManifoldWithConnection M>
struct GeneralSolution : ResultCore {
  /// Every node of the requested problem's discrete solution (at a failure: of the best iterate).
  GeneralTrajectory<M> trajectory;
  manifolds::ComponentsOf<M> v0 = manifolds::ComponentsOf<M>::Zero();
  manifolds::ComponentMatrixOf<M> Xi0 = manifolds::ComponentMatrixOf<M>::Zero();
};

/// Quantities along a sampled solution (along.hpp), one entry per sample: the parallel frame E_k,
/// u_k = E_k v_k, the energy E_k = mu.v - l and the cumulative discrete action (0 first, the action
/// last).
template <manifolds::ManifoldWithConnection M>
struct GeneralAlong {
  std::vector<manifolds::FrameOf<M>> frame;
  std::vector<manifolds::VectorOf<M>> u;
  std::vector<double> energy, action;
};

/// The Lie-group shooting's options (order, tolerance, max_iterations, analytic_jacobian: the
/// tangent-linear sweep of tangent.hpp, no_progress_window, monitor), so that the continuation
/// path (methods/lie_group/continuation.hpp) drives both problem families.
using GeneralShootingOptions = ShootingOptions;

template <manifolds::ManifoldWithConnection M>
struct GeneralGuess {
  std::optional<manifolds::ComponentsOf<M>> v0;
  std::optional<manifolds::ComponentMatrixOf<M>> Xi0;
  /// A whole trajectory from 0 to T (e.g. an earlier solution): the start of collocation, and its
  /// first node the (v0, Xi0) of shooting.
  std::optional<GeneralTrajectory<M>> trajectory;

  bool empty() const { return !v0 && !Xi0 && !trajectory; }
  /// The guess of v(0) and of Xi(0): given directly, or the trajectory's first node; none if neither.
  std::optional<manifolds::ComponentsOf<M>> start_v0() const {
    return v0 ? v0 : trajectory ? std::optional(trajectory->v.front()) : std::nullopt;
  }
  std::optional<manifolds::ComponentMatrixOf<M>> start_Xi0() const {
    return Xi0 ? Xi0 : trajectory ? std::optional(trajectory->Xi.front()) : std::nullopt;
  }
};

}  // namespace cartan::general
