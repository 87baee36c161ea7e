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
  using Types = mechanics::TermTypes<M, manifolds::PointOf<M>, manifolds::ComponentsOf<M>, manifolds::ComponentsOf<M>,
                                     manifolds::VectorOf<M>, LagrangianHessian<M>>;
  static constexpr bool kOnGroup = false;
  template <class L>
  static constexpr bool wraps = ManifoldLagrangian<L, M>;
  /// What check_lagrangian checks (has_hessian()).
  template <class L>
  static constexpr bool has_hessian =
      requires(const L& l, const M& m, double t, const manifolds::PointOf<M>& q, const manifolds::ComponentsOf<M>& v) {
        l.hessian(m, t, q, v);
      };
  template <class L, class... Args>  // (t, q, v)
  static manifolds::VectorOf<M> gradient(const L& l, const Args&... at) {
    return l.point_gradient(at...);
  }
  template <class L, class... Args>  // (t, q, v)
  static LagrangianHessian<M> hessian(const L& l, const M* manifold, const Args&... at) {
    return lagrangian_hessian(*manifold, l, at...);
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
