#pragma once
// What the library compiles of the mechanics on manifolds, as declarations, for every shipped
// manifold (manifolds/shipped.hpp) and the erased Lagrangian: the check of a Lagrangian's callbacks
// and its seeded samples (definitions: manifold_check_lagrangian.hpp), and the erased particle
// (manifold_erased_lagrangian.hpp, manifold_particle.hpp). Defined in src/methods/solve_<manifold>.cpp
// with the general kernel's entry points (kernels/manifold/compiled.hpp).

#include <vector>

#include "cartan/manifolds/shipped.hpp"
#include "cartan/mechanics/check_report.hpp"
#include "cartan/mechanics/manifold_erased_lagrangian.hpp"
#include "cartan/mechanics/manifold_lagrangian.hpp"

namespace cartan::general {

/// A Lagrangian's callbacks against each other at the samples, and seeded samples around `base`
/// (mechanics/manifold_check_lagrangian.hpp).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
mechanics::CheckReport check_lagrangian(const M& manifold, const L& l, const std::vector<ManifoldLagrangianSample<M>>& samples);
template <manifolds::ManifoldWithConnection M>
std::vector<ManifoldLagrangianSample<M>> lagrangian_samples(const M& manifold, const manifolds::PointOf<M>& base,
                                                            const mechanics::CheckLagrangianOptions& options);

}  // namespace cartan::general

/// `extern template` (declaration) or `template` (definition) of the check, its samples and the
/// erased particle on M.
#define CARTAN_MECHANICS_MANIFOLD_COMPILED(prefix, M)                                                      \
  prefix ::cartan::mechanics::CheckReport cartan::general::check_lagrangian(                               \
      const M&, const ::cartan::general::ErasedLagrangian<M>&,                                             \
      const std::vector<::cartan::general::ManifoldLagrangianSample<M>>&);                                 \
  prefix std::vector<::cartan::general::ManifoldLagrangianSample<M>> cartan::general::lagrangian_samples(  \
      const M&, const ::cartan::manifolds::PointOf<M>&, const ::cartan::mechanics::CheckLagrangianOptions&); \
  prefix ::cartan::general::ErasedLagrangian<M> cartan::general::erased_particle(                          \
      const ::cartan::manifolds::ComponentMatrixOf<M>&, ::cartan::general::ParticlePotential<M>,           \
      ::cartan::general::ParticleGradient<M>);                                                             \
  prefix ::cartan::general::ErasedLagrangian<M> cartan::general::erased_particle_in_linear_potential(      \
      const ::cartan::manifolds::ComponentMatrixOf<M>&, const ::cartan::manifolds::VectorOf<M>&);

#define CARTAN_MECHANICS_MANIFOLD_EXTERN(M) CARTAN_MECHANICS_MANIFOLD_COMPILED(extern template, M)
CARTAN_GENERAL_SHIPPED_MANIFOLDS(CARTAN_MECHANICS_MANIFOLD_EXTERN)
#undef CARTAN_MECHANICS_MANIFOLD_EXTERN
