// The general solve and verify on R^2 with constant Christoffel symbols for the erased Lagrangian, compiled once
// (compiled.hpp).
#include "cartan/kernels/manifold/along.hpp"
#include "cartan/kernels/manifold/verify.hpp"
#include "cartan/mechanics/manifold_check_lagrangian.hpp"
#include "cartan/mechanics/manifold_particle.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/methods/solve.hpp"

CARTAN_GENERAL_COMPILED(template, ::cartan::manifolds::Euclidean<2>)
