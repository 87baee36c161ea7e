#pragma once
// The free rigid body and the harmonic oscillator on SO(3) (paper §"Application to the rigid
// body", appendix "The harmonic oscillator"), left-reduced (body frame):
//   free body:   l(g, v) = 1/2 v . I v,                 h(g, mu) = 1/2 mu . I^{-1} mu,
//   oscillator:  l(g, v) = 1/2 v . I v - V(g),          V(g) = 1/2 (3 - tr g),
// with any symmetric positive-definite inertia I (validated, mechanics/natural_system.hpp).
// Right-reduced (spatial) forms: RightReducedLagrangian / RightReducedHamiltonian
// (mechanics/right_reduced.hpp); for the free body l_+(g, v) = 1/2 (Ad_{g^-1} v) . I (Ad_{g^-1} v)
// with right-trivialised group gradient zeta_+ = ad*_v mu (derived there).

#include "cartan/mechanics/natural_system.hpp"
#include "cartan/mechanics/right_reduced.hpp"
#include "cartan/groups/so3.hpp"

namespace cartan::mechanics {

/// V(g) = 1/2 (3 - tr g) ~ theta^2 / 2 for a rotation by a small angle theta, evaluated as
/// 1/4 |g - I|_F^2 (equal on SO(3): |g - I|^2 = 6 - 2 tr g), whose roundoff is relative to V
/// (eps theta^2) where 3 - tr g's is eps: at theta = 1e-9 that was the whole of V, and the energy
/// E = mu.v - l ~ 1e-18 drifted by 0.34 of itself, failing verify with every method.
/// Left gradient: d/de V(g exp(e w)) = -1/2 tr(g hat(w)) = vee(Skew g) . w, since
/// tr(g hat(w)) = -2 vee(Skew g) . w. So the oscillator's zeta = -dV = -vee(Skew g), a restoring
/// force (docs/paper-notes.md#erratum-1: the paper prints +vee(Skew g), the gradient of V).
struct SO3TracePotential {
  double value(const groups::SO3::Element& g) const { return (g - groups::SO3::Element::Identity()).squaredNorm() / 4; }
  groups::SO3::Tangent left_gradient(const groups::SO3::Element& g) const { return groups::SO3::vee(g); }  // vee reads Skew(g)
  /// d/de vee(Skew(g exp(e E_i))) = vee(Skew(g hat(E_i))).
  groups::SO3::AlgebraMatrix left_hessian(const groups::SO3::Element& g) const {
    groups::SO3::AlgebraMatrix h;
    for (int i = 0; i < 3; ++i) h.col(i) = groups::SO3::vee(g * groups::SO3::hat(groups::SO3::Tangent::Unit(i)));
    return h;
  }
};

using RigidBody = NaturalLagrangian<groups::SO3, ZeroPotential<groups::SO3>>;
using RigidBodyHamiltonian = NaturalHamiltonian<groups::SO3, ZeroPotential<groups::SO3>>;
using SpatialRigidBody = RightReducedLagrangian<groups::SO3, RigidBody>;
using SpatialRigidBodyHamiltonian = RightReducedHamiltonian<groups::SO3, RigidBodyHamiltonian>;

using SO3Oscillator = NaturalLagrangian<groups::SO3, SO3TracePotential>;
using SO3OscillatorHamiltonian = NaturalHamiltonian<groups::SO3, SO3TracePotential>;

}  // namespace cartan::mechanics
