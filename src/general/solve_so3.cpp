// The general solve and verify on SO(3) with a left-invariant connection for the erased Lagrangian, compiled once
// (compiled.hpp).
#include "cartan/general/compiled.hpp"

CARTAN_GENERAL_COMPILED(template, ::cartan::manifolds::GroupManifold<::cartan::groups::SO3>)
