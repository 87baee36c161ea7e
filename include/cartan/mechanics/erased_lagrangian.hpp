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
  static constexpr bool kOnGroup = true;
  using Space = G;
  using Point = groups::ElementOf<G>;
  using Velocity = groups::TangentOf<G>;
  using Momentum = groups::CovectorOf<G>;
  using Gradient = groups::CovectorOf<G>;
  using Hessian = LagrangianHessian<G>;

  template <class L>
  static constexpr bool wraps = ReducedLagrangian<L, G>;
  /// Whether lagrangian_hessian takes L's own (Erased reports it on a manifold only).
  template <class L>
  static constexpr bool has_hessian = requires(const L& l, double t, const Point& g, const Velocity& v) {
    { l.hessian(t, g, v) } -> std::convertible_to<Hessian>;
  };
  template <class L>
  static Gradient gradient(const L& l, double t, const Point& g, const Velocity& v) {
    return l.group_gradient(t, g, v);
  }
  template <class L>
  static Hessian hessian(const L& l, const G*, double t, const Point& g, const Velocity& v) {
    return lagrangian_hessian<G>(l, t, g, v);
  }
};

template <groups::LieGroup G>
using ErasedLagrangian = Erased<ReducedTerms<G>>;

}  // namespace cartan::mechanics
