#pragma once
// The transported solver's entry points as declarations, and the list of what the library compiles
// of them: what a unit needs to call the library without parsing a solver. Including this header
// costs a unit seconds; instantiating the solve costs it tens of seconds and 0.4-1 GB of compiler
// memory per Lagrangian (bench/README.md, "Build time").
//
// Compiled in the library (src/kernels/lie_group/), for
//   - every built-in model (CARTAN_TRANSPORTED_BUILTIN_MODELS): solve and validate;
//   - the erased Lagrangian (mechanics/erased_lagrangian.hpp; `erased(problem)` puts any
//     Lagrangian behind it) on every shipped group (CARTAN_TRANSPORTED_SHIPPED_GROUPS): solve,
//     validate, verify_trajectory, along_solution and along_transport, and single shooting
//     (solve_shooting, declared where it is defined: shooting.hpp).
// A call with any other Lagrangian through this header alone does not link: call it as
// `solve(erased(problem))`, or include the definitions (solve.hpp, along.hpp, kernels/lie_group/verify.hpp)
// for the fully typed instantiation (faster to run, slower to compile). The definition headers
// include this one, so the declarations (with the default arguments) are written once.

#include <type_traits>

#include "cartan/groups/shipped.hpp"
#include "cartan/kernels/lie_group/solution.hpp"
#include "cartan/kernels/lie_group/solve_options.hpp"
#include "cartan/mechanics/erased_lagrangian.hpp"
#include "cartan/principle/group_problem.hpp"
#include "cartan/status.hpp"
#include "cartan/verify/verdict.hpp"

/// The built-in models whose own solve the library compiles, one X(G, L) each
/// (src/methods/lie_group/solve_*.cpp; declared `extern template` in solve.hpp, where their definition is
/// visible: a unit that sees the declaration alone cannot instantiate them anyway).
#define CARTAN_TRANSPORTED_BUILTIN_MODELS(X)                          \
  X(::cartan::groups::SO3, ::cartan::mechanics::RigidBody)            \
  X(::cartan::groups::SO3, ::cartan::mechanics::SO3Oscillator)        \
  X(::cartan::groups::Heisenberg, ::cartan::mechanics::H3Oscillator)  \
  X(::cartan::groups::SE2, ::cartan::mechanics::SE2FreeBody)          \
  X(::cartan::groups::SE3, ::cartan::mechanics::SE3FreeBody)

namespace cartan::transported {

/// The problem of the compiled solve on G: any Lagrangian behind the erased type.
template <groups::LieGroup G>
using ErasedProblem = TransportedProblem<G, mechanics::ErasedLagrangian<G>>;

/// `problem` with its Lagrangian behind the erased type (for the compiled solve and verify).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
ErasedProblem<G> erased(const TransportedProblem<G, L>& problem) {
  return {mechanics::ErasedLagrangian<G>(problem.lagrangian), problem.lambda, problem.T, problem.N, problem.g0, problem.gT};
}

/// Whether the library compiles the erased Lagrangian's entry points on G.
#define CARTAN_TRANSPORTED_IS_SHIPPED(Shipped) std::is_same_v<G, Shipped> ||
template <class G>
inline constexpr bool kCompiledGroup = CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_TRANSPORTED_IS_SHIPPED) false;
#undef CARTAN_TRANSPORTED_IS_SHIPPED

/// Solves `problem` as `options` say (solve.hpp). Throws std::invalid_argument for a bad problem,
/// options or guess (validate), before any work; numerical failures are statuses.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve(const TransportedProblem<G, L>& problem, const SolveOptions& options = {},
                             const SolveGuess<G>& guess = {});

/// Throws std::invalid_argument for every problem, options and guess that solve() rejects, and
/// does no other work (solve.hpp; a sweep checks all its problems before it solves any).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void validate(const TransportedProblem<G, L>& problem, const SolveOptions& options = {}, const SolveGuess<G>& guess = {});

/// P_k, u_k, the energy and the cumulative action along a sampled solution (along.hpp).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
AlongSolution<G> along_solution(const L& lagrangian, double lambda, const TransportedTrajectory<G>& x);
/// P_k and u_k alone: no Lagrangian (along.hpp).
template <groups::LieGroup G>
AlongSolution<G> along_transport(double lambda, const TransportedTrajectory<G>& x);

}  // namespace cartan::transported

namespace cartan::verify {

/// Every check on `x` as a solution of `problem`, computed to `tol` by a method of the given order
/// (kernels/lie_group/verify.hpp); a `status` other than converged adds a failing `converged` check.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
Report verify_trajectory(const transported::TransportedProblem<G, L>& problem, transported::TransportedTrajectory<G> x,
                         int order, double tol, Status status = Status::Converged);

/// verify_trajectory on a solver's result: its trajectory, order and status. A result without a
/// trajectory (a failure that kept no iterate) gets the failing `converged` check alone.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
Report verify_solution(const transported::TransportedProblem<G, L>& problem, const transported::TransportedSolution<G>& solution, double tol) {
  if (solution.trajectory.t.empty() && !solution.converged()) return unchecked_failure(solution.status);
  return verify_trajectory(problem, solution.trajectory, solution.order, tol, solution.status);
}

}  // namespace cartan::verify

/// `extern template` (declaration, below) or `template` (definition, in src/kernels/lie_group/) of what
/// the library compiles for the Lagrangian L on G, and of what it compiles for the erased
/// Lagrangian on G besides.
#define CARTAN_TRANSPORTED_COMPILED_MODEL(prefix, G, L)                                                               \
  prefix ::cartan::transported::TransportedSolution<G> cartan::transported::solve(                                     \
      const ::cartan::transported::TransportedProblem<G, L>&, const ::cartan::transported::SolveOptions&,             \
      const ::cartan::transported::SolveGuess<G>&);                                                                    \
  prefix void cartan::transported::validate(const ::cartan::transported::TransportedProblem<G, L>&,                   \
                                            const ::cartan::transported::SolveOptions&,                               \
                                            const ::cartan::transported::SolveGuess<G>&);
#define CARTAN_TRANSPORTED_COMPILED_ERASED(prefix, G)                                                                 \
  CARTAN_TRANSPORTED_COMPILED_MODEL(prefix, G, ::cartan::mechanics::ErasedLagrangian<G>)                              \
  prefix ::cartan::verify::Report cartan::verify::verify_trajectory(                                                   \
      const ::cartan::transported::ErasedProblem<G>&, ::cartan::transported::TransportedTrajectory<G>, int, double,   \
      ::cartan::Status);                                                                                               \
  prefix ::cartan::transported::AlongSolution<G> cartan::transported::along_solution(                                 \
      const ::cartan::mechanics::ErasedLagrangian<G>&, double, const ::cartan::transported::TransportedTrajectory<G>&); \
  prefix ::cartan::transported::AlongSolution<G> cartan::transported::along_transport(                                \
      double, const ::cartan::transported::TransportedTrajectory<G>&);

#define CARTAN_TRANSPORTED_EXTERN_ERASED(G) CARTAN_TRANSPORTED_COMPILED_ERASED(extern template, G)
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_TRANSPORTED_EXTERN_ERASED)
#undef CARTAN_TRANSPORTED_EXTERN_ERASED
