#pragma once
// Any Lagrangian of the general problem behind one type per manifold: ErasedLagrangian<M>, the
// erased Lagrangian (erased.hpp) in the terms of ManifoldLagrangian<M> (manifold_lagrangian.hpp):
// value, momentum, velocity, point_gradient, hessian(manifold, t, q, v)
// (manifold_lagrangian_hessian.hpp), has_hessian() and hessian_structure(); and the particle behind
// it (declared here, defined in manifold_particle.hpp). The general solve and verify are compiled
// once for it on every shipped manifold (kernels/manifold/compiled.hpp, which also holds its
// problem, ErasedProblem<M>, and erased(problem); src/methods/solve_<space>.cpp), so that the CLI,
// the Python module and a user's own Lagrangian reuse them.

#include <concepts>
#include <functional>

#include "cartan/mechanics/erased.hpp"
#include "cartan/mechanics/manifold_lagrangian.hpp"
#include "cartan/mechanics/manifold_lagrangian_hessian.hpp"

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

/// The potential of a particle, V(q), and its ambient gradient (KineticPotential, manifold_lagrangian.hpp).
template <manifolds::ManifoldWithConnection M>
using ParticlePotential = std::function<double(const manifolds::PointOf<M>&)>;
template <manifolds::ManifoldWithConnection M>
using ParticleGradient = std::function<manifolds::VectorOf<M>(const manifolds::PointOf<M>&)>;

/// The particle l = 1/2 v^T A v - V(q) (KineticPotential: A symmetric positive definite in frame
/// components, V and its gradient both or neither) behind the erased Lagrangian; with V = c . q for
/// the second, where points are vectors (else it throws std::invalid_argument). Compiled in the
/// library (manifold_particle.hpp), so that a caller does not compile the particle's callbacks.
/// Throws std::invalid_argument as KineticPotential does.
template <manifolds::ManifoldWithConnection M>
ErasedLagrangian<M> erased_particle(const manifolds::ComponentMatrixOf<M>& inertia, ParticlePotential<M> potential = {},
                                    ParticleGradient<M> gradient = {});
template <manifolds::ManifoldWithConnection M>
ErasedLagrangian<M> erased_particle_in_linear_potential(const manifolds::ComponentMatrixOf<M>& inertia,
                                                        const manifolds::VectorOf<M>& c);

}  // namespace cartan::general
