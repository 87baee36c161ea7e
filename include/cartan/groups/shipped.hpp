#pragma once
// The groups the library compiles the Lie-group kernel for, one X(...) each: the one list that the
// kernel's declarations (kernels/lie_group/compiled.hpp), its compiled units (src/methods/lie_group/,
// src/kernels/lie_group/) and the api's doors for objects (src/api/) instantiate. The manifolds'
// list, which holds these groups as group manifolds, is manifolds/shipped.hpp: a unit that solves
// on groups only does not parse the manifolds' headers.

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"

/// The groups of the Lie-group kernel's compiled entry points for the erased Lagrangian.
#define CARTAN_TRANSPORTED_SHIPPED_GROUPS(X) \
  X(::cartan::groups::SO3)                   \
  X(::cartan::groups::Heisenberg)            \
  X(::cartan::groups::SE2)                   \
  X(::cartan::groups::SE3)
