#pragma once
// The definitions of erased_particle and erased_particle_in_linear_potential (declared in
// manifold_erased_lagrangian.hpp): the particle l = 1/2 v^T A v - V(q) (KineticPotential,
// manifold_lagrangian.hpp) behind the erased Lagrangian. Included only where the library compiles
// them (src/methods/solve_<manifold>.cpp, extern template in kernels/manifold/compiled.hpp), so that
// the api and the Python module call the library's instantiation, at its optimisation, instead of
// compiling the particle's callbacks again (bench/README.md, "Build time").

#include <utility>

#include "cartan/errors.hpp"
#include "cartan/mechanics/manifold_erased_lagrangian.hpp"
#include "cartan/mechanics/manifold_lagrangian.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M>
ErasedLagrangian<M> erased_particle(const manifolds::ComponentMatrixOf<M>& inertia, ParticlePotential<M> potential,
                                    ParticleGradient<M> gradient) {
  return ErasedLagrangian<M>(KineticPotential<M>(inertia, std::move(potential), std::move(gradient)));
}

template <manifolds::ManifoldWithConnection M>
ErasedLagrangian<M> erased_particle_in_linear_potential(const manifolds::ComponentMatrixOf<M>& inertia,
                                                        const manifolds::VectorOf<M>& c) {
  if constexpr (manifolds::PointOf<M>::ColsAtCompileTime == 1) {
    return ErasedLagrangian<M>(KineticPotential<M>::with_linear_potential(inertia, c));
  } else {
    throw_invalid("erased_particle_in_linear_potential", "c", format_value(c),
                  "is a uniform field, which needs points that are vectors (this manifold's are matrices)");
  }
}

}  // namespace cartan::general
