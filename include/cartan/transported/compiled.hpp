#pragma once
// The transported solve and verify (solve.hpp, verify/report.hpp) compiled once in the library for
// the erased Lagrangian (mechanics/erased_lagrangian.hpp; `erased(problem)` wraps any problem's)
// on every shipped group: SO(3), H3, SE(2), SE(3). Including this header instead of instantiating
// them costs a unit seconds rather than tens of seconds per Lagrangian (bench/README.md, "Build
// time"); the definitions are in src/transported/, one file per group
// (CARTAN_TRANSPORTED_SHIPPED_GROUPS, erased_solve.hpp), compiled in the library's
// `transported_erased` unity group (CMakeLists.txt). The Python module solves its Lagrangians
// written in Python through them. Built-in models keep their own compiled instantiations
// (solve.hpp).

#include "cartan/transported/erased_solve.hpp"
#include "cartan/transported/solve.hpp"
#include "cartan/verify/report.hpp"

namespace cartan::transported {

template <groups::LieGroup G>
TransportedSolution<G> solve_erased(const ErasedProblem<G>& problem, const SolveOptions& options,
                                    const SolveGuess<G>& guess) {
  return solve(problem, options, guess);
}

}  // namespace cartan::transported

/// `extern template` (declaration) or `template` (definition, in src/transported/) of the solve
/// (also as solve_erased, erased_solve.hpp) and the verifier for the erased Lagrangian on G.
#define CARTAN_TRANSPORTED_COMPILED(prefix, G)                                                                  \
  prefix ::cartan::transported::TransportedSolution<G> cartan::transported::solve(                             \
      const ::cartan::transported::ErasedProblem<G>&, const ::cartan::transported::SolveOptions&,              \
      const ::cartan::transported::SolveGuess<G>&);                                                            \
  prefix ::cartan::transported::TransportedSolution<G> cartan::transported::solve_erased<G>(                   \
      const ::cartan::transported::ErasedProblem<G>&, const ::cartan::transported::SolveOptions&,              \
      const ::cartan::transported::SolveGuess<G>&);                                                            \
  prefix ::cartan::verify::Report cartan::verify::verify_trajectory(                                            \
      const ::cartan::transported::ErasedProblem<G>&, ::cartan::transported::TransportedTrajectory<G>, int, double, \
      ::cartan::Status);

#define CARTAN_TRANSPORTED_EXTERN(G) CARTAN_TRANSPORTED_COMPILED(extern template, G)
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_TRANSPORTED_EXTERN)
#undef CARTAN_TRANSPORTED_EXTERN
