#pragma once
// Any Lagrangian of the general problem behind one type per manifold: ErasedLagrangian<M>, the
// erased Lagrangian (mechanics/erased.hpp) in the terms of ManifoldLagrangian<M> (lagrangian.hpp):
// value, momentum, velocity, point_gradient, hessian(manifold, t, q, v) (lagrangian_hessian.hpp),
// has_hessian() and hessian_structure(). The general solve and verify are compiled once for it on
// every shipped manifold (compiled.hpp, src/methods/solve_<space>.cpp), so that the CLI, the
// Python module and a user's own Lagrangian reuse them.

#include <concepts>

#include "cartan/kernels/manifold/lagrangian.hpp"
#include "cartan/kernels/manifold/lagrangian_hessian.hpp"
#include "cartan/kernels/manifold/problem.hpp"
#include "cartan/mechanics/erased.hpp"

namespace cartan::general {

/// A Lagrangian on M as mechanics::Erased reads it.
template <manifolds::ManifoldWithConnection M>
struct ManifoldTerms {
  static constexpr bool kOnGroup = false;
  using Space = M;
  using Point = manifolds::PointOf<M>;
  using Velocity = manifolds::ComponentsOf<M>;
  using Momentum = manifolds::ComponentsOf<M>;
  using Gradient = manifolds::VectorOf<M>;
  using Hessian = LagrangianHessian<M>;

  template <class L>
  static constexpr bool wraps = ManifoldLagrangian<L, M>;
  /// What check_lagrangian checks (has_hessian()).
  template <class L>
  static constexpr bool has_hessian = requires(const L& l, const M& m, double t, const Point& q, const Velocity& v) {
    l.hessian(m, t, q, v);
  };
  template <class L>
  static Gradient gradient(const L& l, double t, const Point& q, const Velocity& v) {
    return l.point_gradient(t, q, v);
  }
  template <class L>
  static Hessian hessian(const L& l, const M* manifold, double t, const Point& q, const Velocity& v) {
    return lagrangian_hessian(*manifold, l, t, q, v);
  }
};

template <manifolds::ManifoldWithConnection M>
using ErasedLagrangian = mechanics::Erased<ManifoldTerms<M>>;

/// The problem of the compiled solve on M (compiled.hpp): any Lagrangian behind the erased type.
template <manifolds::ManifoldWithConnection M>
using ErasedProblem = GeneralProblem<M, ErasedLagrangian<M>>;

/// `problem` with its Lagrangian behind the erased type (for the compiled solvers).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
ErasedProblem<M> erased(const GeneralProblem<M, L>& problem) {
  return {problem.manifold, ErasedLagrangian<M>(problem.lagrangian), problem.T, problem.N, problem.q0, problem.qT,
          problem.frame0};
}

}  // namespace cartan::general
