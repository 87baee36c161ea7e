#pragma once
// The free body on SE(2) and SE(3): a rigid body moving freely in the plane or in space,
// left-reduced (body frame), with kinetic energy only,
//   l(g, v) = 1/2 v . I v,          h(g, mu) = 1/2 mu . I^{-1} mu,
// I a symmetric positive-definite inertia on the Lie algebra in the group's coordinate order
// (SE(2): (x, y, theta), so diag(m, m, J) is a body of mass m and moment J about its centre of
// mass; SE(3): (rho, omega), so diag(m, m, m, J1, J2, J3)). The inertia is validated by the model
// (mechanics/natural_system.hpp, Inertia): an asymmetric (beyond relative 1e-12), non-finite or
// not positive-definite matrix throws std::invalid_argument naming the matrix.
// The Euler--Poincare equation of l is d/dt (I v) = ad*_v (I v); a velocity v with ad*_v (I v) = 0
// (e.g. an eigenvector of a diagonal I along one coordinate axis) is a relative equilibrium,
// g(t) = g0 exp(t v).

#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/mechanics/natural_system.hpp"

namespace cartan::mechanics {

/// l(g, v) = 1/2 v . I v on any group (the rigid body of rigid_body.hpp is FreeBody<SO3>).
template <groups::LieGroup G>
using FreeBody = NaturalLagrangian<G, ZeroPotential<G>>;
template <groups::LieGroup G>
using FreeBodyHamiltonian = NaturalHamiltonian<G, ZeroPotential<G>>;

using SE2FreeBody = FreeBody<groups::SE2>;
using SE2FreeBodyHamiltonian = FreeBodyHamiltonian<groups::SE2>;
using SE3FreeBody = FreeBody<groups::SE3>;
using SE3FreeBodyHamiltonian = FreeBodyHamiltonian<groups::SE3>;

}  // namespace cartan::mechanics
