#pragma once
// The general solve, shooting and verify (solve.hpp, shooting.hpp, verify.hpp) compiled once in the
// library for the erased Lagrangian (erased_lagrangian.hpp; `erased(problem)` wraps any problem's)
// on every shipped manifold: the sphere, the hyperbolic plane, R^2 and R^3 with constant
// Christoffel symbols, charts of dimension 2 and 3, and SO(3), H3, SE(2), SE(3) with any
// left-invariant connection. Including this header instead of instantiating them costs a unit
// seconds rather than tens of seconds per manifold (bench/README.md, "Build time"); the
// definitions are in src/general/, one file per manifold, compiled in unity groups (CMakeLists.txt).
// Any other (manifold, Lagrangian) pair is instantiated where it is used, as before.

#include "cartan/general/erased_lagrangian.hpp"
#include "cartan/general/solve.hpp"
#include "cartan/general/verify.hpp"
#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/manifolds/chart.hpp"
#include "cartan/manifolds/euclidean.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/manifolds/quadric.hpp"

/// The shipped manifolds, one X(M) each (the list of the header comment).
#define CARTAN_GENERAL_SHIPPED_MANIFOLDS(X)                                                              \
  X(::cartan::manifolds::Sphere)                                                                         \
  X(::cartan::manifolds::HyperbolicPlane)                                                                \
  X(::cartan::manifolds::Euclidean<2>)                                                                   \
  X(::cartan::manifolds::Euclidean<3>)                                                                   \
  X(::cartan::manifolds::Chart<2>)                                                                       \
  X(::cartan::manifolds::Chart<3>)                                                                       \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::SO3>)                                           \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::Heisenberg>)                                    \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::SE2>)                                           \
  X(::cartan::manifolds::GroupManifold<::cartan::groups::SE3>)

/// `extern template` (declaration) or `template` (definition, in src/general/) of the solve, the
/// shooting it runs (both entry points) and the verifier for the erased Lagrangian on M.
#define CARTAN_GENERAL_COMPILED(prefix, M)                                                                     \
  prefix ::cartan::general::GeneralSolution<M> cartan::general::solve(                                        \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::transported::SolveOptions&, const ::cartan::general::GeneralGuess<M>&);                  \
  prefix ::cartan::general::GeneralSolution<M> cartan::general::solve_general_shooting(                       \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::general::GeneralShootingOptions&, const ::cartan::manifolds::ComponentsOf<M>&,           \
      const ::cartan::manifolds::ComponentMatrixOf<M>&);                                                       \
  prefix ::cartan::general::GeneralSolution<M> cartan::general::solve_general_shooting(                       \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::general::GeneralShootingOptions&);                                                       \
  prefix ::cartan::verify::Report cartan::general::verify_general(                                              \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::general::GeneralTrajectory<M>&, int, double, ::cartan::Status);

#define CARTAN_GENERAL_EXTERN(M) CARTAN_GENERAL_COMPILED(extern template, M)
CARTAN_GENERAL_SHIPPED_MANIFOLDS(CARTAN_GENERAL_EXTERN)
#undef CARTAN_GENERAL_EXTERN
