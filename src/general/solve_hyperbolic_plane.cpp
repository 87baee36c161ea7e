// The general solve and verify on the hyperbolic plane for the erased Lagrangian, compiled once
// (compiled.hpp).
#include "cartan/general/along.hpp"
#include "cartan/general/check_lagrangian.hpp"
#include "cartan/general/shooting.hpp"
#include "cartan/general/solve.hpp"
#include "cartan/general/verify.hpp"

CARTAN_GENERAL_COMPILED(template, ::cartan::manifolds::HyperbolicPlane)
