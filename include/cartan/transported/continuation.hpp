#pragma once
// Continuation for long horizons (docs/paper-notes.md#erratum-4): the transported-velocity BVP has
// several solutions at long horizons and plain shooting from the geodesic guess may not
// converge. Continuation follows one solution branch from an easy problem:
//  * in T: halve the horizon until shooting from the geodesic guess converges, then lengthen
//    it step by step (same step size h, so N scales with T), each solve starting from the
//    previous (v0, xi0); a failed stage halves the increment.
//  * in lambda: from a solution at lambda_start (e.g. the classical lambda = 0, itself found
//    directly or by continuation in T) to lambda.
// The result records the path in `branch`, e.g. "continued in T from T = 3 (4 stages)".

#include <cmath>
#include <sstream>

#include "cartan/transported/shooting.hpp"

namespace cartan {

struct ContinuationOptions {
  ShootingOptions shooting;
  int max_halvings = 8;     ///< of the horizon, looking for a start that converges
  int max_stages = 200;     ///< successful + failed continuation stages
  double min_increment = 1e-6;  ///< relative to the distance to go; below it the path has failed
  /// A solve counts as a step along the branch only if it converges within this many
  /// iterations; slower convergence may have jumped to another solution branch.
  int quick_iterations = 12;
  int initial_stages = 8;   ///< the first increment is (target - start) / initial_stages

  void validate() const {
    shooting.validate();
    if (max_halvings < 0) throw_invalid("ContinuationOptions", "max_halvings", std::to_string(max_halvings), "must be >= 0");
    if (max_stages < 1) throw_invalid("ContinuationOptions", "max_stages", std::to_string(max_stages), "must be >= 1");
    if (quick_iterations < 1) {
      throw_invalid("ContinuationOptions", "quick_iterations", std::to_string(quick_iterations), "must be >= 1");
    }
    if (initial_stages < 1) {
      throw_invalid("ContinuationOptions", "initial_stages", std::to_string(initial_stages), "must be >= 1");
    }
  }
};

namespace detail {

/// Walks a scalar parameter from `from` to `to`, solving with the previous solution as the
/// guess; `make(s)` builds the problem at parameter s. Accumulates counts into `total`.
/// Every solve on the path is capped at quick_iterations: a slower one would be rejected anyway.
inline ShootingOptions quick_shooting(const ContinuationOptions& options) {
  ShootingOptions quick = options.shooting;
  quick.max_iterations = std::min(quick.max_iterations, options.quick_iterations);
  return quick;
}

template <LieGroup G, class MakeProblem>
TransportedSolution<G> continue_parameter(const MakeProblem& make, double from, double to,
                                          TransportedSolution<G> start, const ContinuationOptions& options,
                                          int& stages, std::ostringstream& path) {
  double s = from;
  double increment = (to - from) / options.initial_stages;
  TransportedSolution<G> current = std::move(start);
  int sweeps = current.sweeps, iterations = current.inner_iterations;
  while (s != to && stages < options.max_stages) {
    const double next = std::abs(to - s) <= std::abs(increment) ? to : s + increment;
    ++stages;
    TransportedSolution<G> trial = solve_shooting(make(next), quick_shooting(options), current.v0, current.xi0);
    sweeps += trial.sweeps;
    iterations += trial.inner_iterations;
    if (trial.converged && trial.inner_iterations <= options.quick_iterations) {
      s = next;
      current = std::move(trial);
      increment *= 1.5;
    } else {
      increment /= 2;
      if (std::abs(increment) < options.min_increment * std::abs(to - from)) break;
    }
  }
  current.sweeps = sweeps;
  current.inner_iterations = iterations;
  if (s != to) {
    current.converged = false;
    current.status = "continuation-failed";
    path << "; stopped at " << format_value(s) << " of " << format_value(to);
  }
  return current;
}

}  // namespace detail

/// Continuation in the horizon T (see the header comment).
template <LieGroup G, ReducedLagrangian<G> L>
TransportedSolution<G> solve_continuation_in_T(const TransportedProblem<G, L>& problem,
                                               const ContinuationOptions& options = {}) {
  problem.validate();
  options.validate();
  const auto start_time = std::chrono::steady_clock::now();
  const double h = problem.step();
  auto make = [&](double horizon) {
    TransportedProblem<G, L> p = problem;
    p.T = horizon;
    p.N = std::max(1, static_cast<int>(std::lround(horizon / h)));
    if (horizon == problem.T) p.N = problem.N;
    return p;
  };
  double start = problem.T;
  TransportedSolution<G> first;
  int sweeps = 0, iterations = 0;
  for (int halving = 0; halving <= options.max_halvings; ++halving, start /= 2) {
    const auto p = make(start);
    first = solve_shooting(p, detail::quick_shooting(options), geodesic_guess(p), CovectorOf<G>::Zero());
    sweeps += first.sweeps;
    iterations += first.inner_iterations;
    if (first.converged && first.inner_iterations <= options.quick_iterations) break;
    first.converged = false;
  }
  first.sweeps = sweeps;
  first.inner_iterations = iterations;
  std::ostringstream path;
  int stages = 0;
  TransportedSolution<G> result = first;
  if (!first.converged) {
    result.status = "continuation-failed";
    path << "no horizon down to T = " << format_value(start * 2) << " converged from the geodesic guess";
  } else if (start == problem.T) {
    path << "direct from the geodesic guess";
  } else {
    path << "continued in T from T = " << format_value(start);
    result = detail::continue_parameter<G>(make, start, problem.T, std::move(first), options, stages, path);
    path << " (" << stages << " stages)";
  }
  result.method = "continuation";
  result.branch = path.str();
  result.message = "continuation in T: " + result.branch + "; " + std::to_string(result.sweeps) +
                   " sweeps in all; last solve: " + result.message;
  result.solve_time_s = detail::seconds_since(start_time);
  return result;
}

/// Continuation in lambda from lambda_start (default 0, the classical left Euler–Poincaré case).
/// The start solution at lambda_start is itself found by solve_continuation_in_T (directly from
/// the geodesic guess when that converges), so that long horizons work too.
template <LieGroup G, ReducedLagrangian<G> L>
TransportedSolution<G> solve_continuation_in_lambda(const TransportedProblem<G, L>& problem,
                                                    double lambda_start = 0.0,
                                                    const ContinuationOptions& options = {}) {
  problem.validate();
  options.validate();
  require_finite(lambda_start, "solve_continuation_in_lambda", "lambda_start");
  const auto start_time = std::chrono::steady_clock::now();
  auto make = [&](double lambda) {
    TransportedProblem<G, L> p = problem;
    p.lambda = lambda;
    return p;
  };
  TransportedSolution<G> first = solve_continuation_in_T(make(lambda_start), options);
  std::ostringstream path;
  int stages = 0;
  TransportedSolution<G> result = first;
  if (!first.converged) {
    result.status = "continuation-failed";
    path << "no solution at lambda = " << format_value(lambda_start) << " (" << first.branch << ")";
  } else {
    path << "continued in lambda from lambda = " << format_value(lambda_start) << " [" << first.branch << "]";
    result = detail::continue_parameter<G>(make, lambda_start, problem.lambda, std::move(first), options, stages, path);
    path << " (" << stages << " stages)";
  }
  result.method = "continuation";
  result.branch = path.str();
  result.message = "continuation in lambda: " + result.branch + "; " + std::to_string(result.sweeps) +
                   " sweeps in all; last solve: " + result.message;
  result.solve_time_s = detail::seconds_since(start_time);
  return result;
}

}  // namespace cartan
