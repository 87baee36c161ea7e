// The general solve and verify on R^2 with constant Christoffel symbols for the erased Lagrangian, compiled once
// (compiled.hpp).
#include "cartan/general/along.hpp"
#include "cartan/general/check_lagrangian.hpp"
#include "cartan/general/shooting.hpp"
#include "cartan/general/solve.hpp"
#include "cartan/general/verify.hpp"

CARTAN_GENERAL_COMPILED(template, ::cartan::manifolds::Euclidean<2>)
