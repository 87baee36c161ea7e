// The general solve and verify on the sphere for the erased Lagrangian, and the
// check of a Lagrangian and the erased particle, compiled once (compiled.hpp, mechanics/manifold_compiled.hpp).
#include "cartan/kernels/manifold/along.hpp"
#include "cartan/kernels/manifold/verify.hpp"
#include "cartan/mechanics/manifold_check_lagrangian.hpp"
#include "cartan/mechanics/manifold_particle.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/methods/solve.hpp"

CARTAN_GENERAL_COMPILED(template, ::cartan::manifolds::Sphere)
CARTAN_MECHANICS_MANIFOLD_COMPILED(template, ::cartan::manifolds::Sphere)
