#pragma once
// Continuation for long horizons (docs/paper-notes.md#erratum-4): the transported-velocity BVP
// has several solutions at long horizons and plain shooting from the geodesic guess may not
// converge. Continuation follows one solution branch from an easy problem:
//  * in T: halve the horizon until shooting from the geodesic guess converges, then lengthen
//    it step by step (same step size h, so N scales with T), each solve starting from the
//    previous (v0, xi0); a failed stage halves the increment.
//  * in lambda: from a solution at lambda_start (e.g. the classical lambda = 0, found directly
//    or by continuation in T) to lambda.
// Work is not wasted: a start or stage whose residual stops decreasing is abandoned after
// no_progress_window iterations, while one that is still converging may finish.
// The result records the path in `branch`, e.g. "continued in T from T = 3 (4 stages)". A
// failed continuation returns the best iterate *of the requested problem* (the direct attempt,
// or a solve from the last stage reached), never a stage's trajectory at another T or lambda,
// and its message says where the path stopped.
// The path itself is solvers/continuation.hpp, written once for every problem family with
// shooting; here the Lie-group kernel's family and its continuation in lambda.

#include <cmath>
#include <optional>
#include <utility>

#include "cartan/methods/lie_group/shooting.hpp"
#include "cartan/solvers/continuation.hpp"

namespace cartan::solvers {

/// The Lie-group kernel's problems on a path: the unknowns (v0, xi0).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
struct ShootingFamily<transported::TransportedProblem<G, L>> {
  using Solution = transported::TransportedSolution<G>;
  using Velocity = groups::TangentOf<G>;
  using Auxiliary = groups::CovectorOf<G>;
  static Solution shoot(const transported::TransportedProblem<G, L>& p, const ShootingOptions& o, const Velocity& v,
                        const Auxiliary& a) {
    return transported::solve_shooting(p, o, v, a);
  }
  static const Velocity& velocity(const Solution& s) { return s.v0; }
  static const Auxiliary& auxiliary(const Solution& s) { return s.xi0; }
  static Velocity guess(const transported::TransportedProblem<G, L>& p) { return transported::geodesic_guess(p); }
  static double auxiliary_scale(const transported::TransportedProblem<G, L>& p) { return transported::xi_scale(p); }
  static constexpr bool kSumsInnerIterations = true;  // along a path (two-level's inner solves too)
};

}  // namespace cartan::solvers

namespace cartan::transported {

/// Continuation in the horizon T (see the header comment). `failed_direct`, when given, is a
/// failed attempt at the full horizon from the same guess with the path's shooting options
/// (the default strategy's first step): it is not repeated, the halving starts at T/2.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_continuation_in_T(const TransportedProblem<G, L>& problem,
                                               const ContinuationOptions& options = {},
                                               std::optional<groups::TangentOf<G>> v0_guess = std::nullopt,
                                               std::optional<groups::CovectorOf<G>> xi0_guess = std::nullopt,
                                               const TransportedSolution<G>* failed_direct = nullptr) {
  problem.validate();
  options.validate();
  std::optional<TransportedSolution<G>> direct;  // the path's own copy, moved from
  if (failed_direct != nullptr) direct = *failed_direct;
  return solvers::detail::continue_in_T(problem, options, v0_guess, xi0_guess, direct ? &*direct : nullptr);
}

/// The same, moving from `failed_direct` instead of copying it (its trajectory may be long).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_continuation_in_T(const TransportedProblem<G, L>& problem,
                                               const ContinuationOptions& options,
                                               std::optional<groups::TangentOf<G>> v0_guess,
                                               std::optional<groups::CovectorOf<G>> xi0_guess,
                                               TransportedSolution<G>&& failed_direct) {
  problem.validate();
  options.validate();
  return solvers::detail::continue_in_T(problem, options, v0_guess, xi0_guess, &failed_direct);
}

/// Continuation in lambda from lambda_start (default 0, the classical left Euler–Poincaré case).
/// The start solution at lambda_start is itself found by solve_continuation_in_T (directly from
/// the geodesic guess when that converges), so that long horizons work too.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_continuation_in_lambda(const TransportedProblem<G, L>& problem,
                                                    double lambda_start = 0.0,
                                                    const ContinuationOptions& options = {}) {
  problem.validate();
  options.validate();
  require_finite(lambda_start, "solve_continuation_in_lambda", "lambda_start");
  return solvers::detail::continue_in_lambda(problem, lambda_start, options);
}

}  // namespace cartan::transported
