#pragma once
// Any reduced Lagrangian on a Lie group G behind one type: ErasedLagrangian<G>, the erased
// Lagrangian (erased.hpp) in the terms of ReducedLagrangian<G> (lagrangian.hpp): value, momentum,
// group_gradient, velocity, hessian(t, g, v) (lagrangian_hessian.hpp) and hessian_structure().
// The transported solve and verify are compiled once for it on every shipped group
// (kernels/lie_group/compiled.hpp, src/methods/lie_group/), so that the Python module's Lagrangians and a
// user's own reuse them.

#include <concepts>

#include "cartan/mechanics/erased.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"

namespace cartan::mechanics {

/// A reduced Lagrangian on G as Erased reads it.
template <groups::LieGroup G>
struct ReducedTerms {
  using Types = TermTypes<G, groups::ElementOf<G>, groups::TangentOf<G>, groups::CovectorOf<G>, groups::CovectorOf<G>,
                          LagrangianHessian<G>>;
  static constexpr bool kOnGroup = true;
  template <class L>
  static constexpr bool wraps = ReducedLagrangian<L, G>;
  /// Whether lagrangian_hessian takes L's own (Erased reports it on a manifold only).
  template <class L>
  static constexpr bool has_hessian =
      requires(const L& l, double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
        { l.hessian(t, g, v) } -> std::convertible_to<LagrangianHessian<G>>;
      };
  template <class L, class... Args>  // (t, g, v)
  static groups::CovectorOf<G> gradient(const L& l, const Args&... at) {
    return l.group_gradient(at...);
  }
  template <class L, class... Args>  // (t, g, v)
  static LagrangianHessian<G> hessian(const L& l, const G*, const Args&... at) {
    return lagrangian_hessian<G>(l, at...);
  }
};

template <groups::LieGroup G>
using ErasedLagrangian = Erased<ReducedTerms<G>>;

}  // namespace cartan::mechanics
