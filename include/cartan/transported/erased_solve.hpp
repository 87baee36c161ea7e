#pragma once
// The erased reduced Lagrangian's problem and its solve as a declaration only: what a unit needs to
// call the library's compiled transported::solve for it (transported/compiled.hpp) without parsing
// the solvers. general::solve reaches the Lie-group kernel's own methods through it
// (general/solve.hpp): the general units stay as light as before (the solvers' headers cost a
// unit about 170 MB of compiler memory; bench/README.md, "Build time").

#include <type_traits>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/mechanics/erased_lagrangian.hpp"
#include "cartan/transported/problem.hpp"
#include "cartan/transported/solution.hpp"
#include "cartan/transported/solve_options.hpp"

/// The groups on which the library compiles the erased solve and verify, one X(G) each
/// (src/transported/erased_*.cpp; compiled.hpp).
#define CARTAN_TRANSPORTED_SHIPPED_GROUPS(X) \
  X(::cartan::groups::SO3)                   \
  X(::cartan::groups::Heisenberg)            \
  X(::cartan::groups::SE2)                   \
  X(::cartan::groups::SE3)

namespace cartan::transported {

/// The problem of the compiled solve on G: any Lagrangian behind the erased type.
template <groups::LieGroup G>
using ErasedProblem = TransportedProblem<G, mechanics::ErasedLagrangian<G>>;

/// `problem` with its Lagrangian behind the erased type (for the compiled solve and verify).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
ErasedProblem<G> erased(const TransportedProblem<G, L>& problem) {
  return {mechanics::ErasedLagrangian<G>(problem.lagrangian), problem.lambda, problem.T, problem.N, problem.g0, problem.gT};
}

/// Whether the library compiles the erased solve and verify on G (CARTAN_TRANSPORTED_SHIPPED_GROUPS).
#define CARTAN_TRANSPORTED_IS_SHIPPED(Shipped) std::is_same_v<G, Shipped> ||
template <class G>
inline constexpr bool kCompiledGroup = CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_TRANSPORTED_IS_SHIPPED) false;
#undef CARTAN_TRANSPORTED_IS_SHIPPED

/// solve(problem, options, guess) (solve.hpp) for the erased Lagrangian: defined in compiled.hpp and
/// compiled in the library for every kCompiledGroup; declared here so that a caller needs no more.
template <groups::LieGroup G>
TransportedSolution<G> solve_erased(const ErasedProblem<G>& problem, const SolveOptions& options,
                                    const SolveGuess<G>& guess);

}  // namespace cartan::transported
