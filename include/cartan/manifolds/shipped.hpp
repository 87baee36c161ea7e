#pragma once
// The manifolds the library compiles the general kernel for, one X(...) each: the one list that the
// kernel's declarations (kernels/manifold/compiled.hpp), the mechanics compiled for manifolds
// (mechanics/manifold_compiled.hpp) and the api's doors for objects (src/api/) instantiate. The
// groups' list (the Lie-group kernel's) is groups/shipped.hpp.

#include "cartan/groups/shipped.hpp"
#include "cartan/manifolds/chart.hpp"
#include "cartan/manifolds/euclidean.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/manifolds/quadric.hpp"

/// The manifolds of the general kernel's: the sphere, the hyperbolic plane, R^2 and R^3 with
/// constant Christoffel symbols, charts of dimension 2 and 3, and SO(3), H3, SE(2), SE(3) with any
/// left-invariant connection.
#define CARTAN_GENERAL_SHIPPED_MANIFOLDS(X)                           \
  X(::cartan::manifolds::Sphere)                                      \
  X(::cartan::manifolds::HyperbolicPlane)                             \
  X(::cartan::manifolds::Euclidean<2>)                                \
  X(::cartan::manifolds::Euclidean<3>)                                \
  X(::cartan::manifolds::Chart<2>)                                    \
  X(::cartan::manifolds::Chart<3>)                                    \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::SO3>)        \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::Heisenberg>) \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::SE2>)        \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::SE3>)
