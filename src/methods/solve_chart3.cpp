// The general solve and verify on a chart of dimension 3 for the erased Lagrangian, compiled once
// (compiled.hpp).
#include "cartan/kernels/manifold/along.hpp"
#include "cartan/kernels/manifold/verify.hpp"
#include "cartan/mechanics/manifold_check_lagrangian.hpp"
#include "cartan/mechanics/manifold_particle.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/methods/solve.hpp"

CARTAN_GENERAL_COMPILED(template, ::cartan::manifolds::Chart<3>)
