#pragma once
// The free rigid body and the harmonic oscillator on SO(3) (paper §"Application to the rigid
// body", appendix "The harmonic oscillator"), left-reduced (body frame):
//   free body:   l(g, v) = 1/2 v . I v,                 h(g, mu) = 1/2 mu . I^{-1} mu,
//   oscillator:  l(g, v) = 1/2 v . I v - V(g),          V(g) = 1/2 (3 - tr g),
// with any symmetric positive-definite inertia I (validated, models/natural_system.hpp).
// Right-reduced (spatial) forms: RightReducedLagrangian / RightReducedHamiltonian
// (models/right_reduced.hpp); for the free body l_+(g, v) = 1/2 (Ad_{g^-1} v) . I (Ad_{g^-1} v)
// with right-trivialised group gradient zeta_+ = ad*_v mu (derived there).

#include "cartan/models/natural_system.hpp"
#include "cartan/models/right_reduced.hpp"
#include "cartan/so3.hpp"

namespace cartan {

/// V(g) = 1/2 (3 - tr g) ~ theta^2 / 2 for a rotation by a small angle theta.
/// Left gradient: d/de V(g exp(e w)) = -1/2 tr(g hat(w)) = vee(Skew g) . w, since
/// tr(g hat(w)) = -2 vee(Skew g) . w. So the oscillator's zeta = -dV = -vee(Skew g), a restoring
/// force (docs/paper-notes.md#erratum-1: the paper prints +vee(Skew g), the gradient of V).
struct SO3TracePotential {
  double value(const SO3::Element& g) const { return (3 - g.trace()) / 2; }
  SO3::Tangent left_gradient(const SO3::Element& g) const { return SO3::vee(g); }  // vee reads Skew(g)
  /// d/de vee(Skew(g exp(e E_i))) = vee(Skew(g hat(E_i))).
  SO3::AlgebraMatrix left_hessian(const SO3::Element& g) const {
    SO3::AlgebraMatrix h;
    for (int i = 0; i < 3; ++i) h.col(i) = SO3::vee(g * SO3::hat(SO3::Tangent::Unit(i)));
    return h;
  }
};

using RigidBody = NaturalLagrangian<SO3, ZeroPotential<SO3>>;
using RigidBodyHamiltonian = NaturalHamiltonian<SO3, ZeroPotential<SO3>>;
using SpatialRigidBody = RightReducedLagrangian<SO3, RigidBody>;
using SpatialRigidBodyHamiltonian = RightReducedHamiltonian<SO3, RigidBodyHamiltonian>;

using SO3Oscillator = NaturalLagrangian<SO3, SO3TracePotential>;
using SO3OscillatorHamiltonian = NaturalHamiltonian<SO3, SO3TracePotential>;

}  // namespace cartan
