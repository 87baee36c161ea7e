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
// The path is written once for every problem family with shooting: ShootingFamily<Problem> says
// how to shoot and where the unknowns (a velocity and an auxiliary: (v0, xi0) here, (v0, Xi0) for
// the general problem, general/solve.hpp) live in a solution.

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>
#include <sstream>

#include "cartan/transported/shooting.hpp"

namespace cartan::transported {

struct ContinuationOptions {
  ShootingOptions shooting;
  int max_halvings = 8;         ///< of the horizon, looking for a start that converges
  int max_stages = 200;         ///< successful + failed continuation stages
  double min_increment = 1e-6;  ///< relative to the distance to go; below it the path has failed
  int no_progress_window = 6;   ///< starts and stages whose |r| does not halve in this many iterations are abandoned
  int initial_stages = 8;       ///< the first increment is (target - start) / initial_stages
  /// A stage is accepted only if its solution lies within this relative distance of the
  /// predictor (continue_parameter); farther means it jumped to another branch.
  double max_correction = 0.1;
  /// Increment control by the predictor's quality: a stage whose scaled residual at the
  /// prediction exceeds this is abandoned after that one evaluation and retried with half the
  /// increment (solving from a poor prediction costs many damped iterations; bench/README.md,
  /// "Continuation increments"). Infinite: no limit.
  double max_stage_residual = 1.0;
  /// The same limit for the starts at halved horizons (not the requested one): a start whose
  /// residual at the guess exceeds it goes on to the next halving at once.
  double max_start_residual = 2.0;
  /// Intermediate stages only feed the predictor: they are solved to
  /// max(shooting tolerance, stage_tolerance); the last stage to the shooting tolerance.
  double stage_tolerance = 1e-4;

  void validate() const {
    shooting.validate();
    if (max_halvings < 0) throw_invalid("ContinuationOptions", "max_halvings", std::to_string(max_halvings), "must be >= 0");
    if (max_stages < 1) throw_invalid("ContinuationOptions", "max_stages", std::to_string(max_stages), "must be >= 1");
    if (no_progress_window < 1) {
      throw_invalid("ContinuationOptions", "no_progress_window", std::to_string(no_progress_window), "must be >= 1");
    }
    if (!(max_correction > 0)) {
      throw_invalid("ContinuationOptions", "max_correction", format_value(max_correction), "must be positive");
    }
    if (initial_stages < 1) {
      throw_invalid("ContinuationOptions", "initial_stages", std::to_string(initial_stages), "must be >= 1");
    }
    if (!(max_stage_residual > 0)) {
      throw_invalid("ContinuationOptions", "max_stage_residual", format_value(max_stage_residual), "must be positive");
    }
    if (!(max_start_residual > 0)) {
      throw_invalid("ContinuationOptions", "max_start_residual", format_value(max_start_residual), "must be positive");
    }
    if (!(stage_tolerance > 0)) {
      throw_invalid("ContinuationOptions", "stage_tolerance", format_value(stage_tolerance), "must be positive");
    }
  }
};

/// How continuation drives shooting on one problem family (header comment).
template <class Problem>
struct ShootingFamily;

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
struct ShootingFamily<TransportedProblem<G, L>> {
  using Solution = TransportedSolution<G>;
  using Velocity = groups::TangentOf<G>;
  using Auxiliary = groups::CovectorOf<G>;
  static Solution shoot(const TransportedProblem<G, L>& p, const ShootingOptions& o, const Velocity& v,
                        const Auxiliary& a) {
    return solve_shooting(p, o, v, a);
  }
  static const Velocity& velocity(const Solution& s) { return s.v0; }
  static const Auxiliary& auxiliary(const Solution& s) { return s.xi0; }
  static Velocity guess(const TransportedProblem<G, L>& p) { return geodesic_guess(p); }
  static double auxiliary_scale(const TransportedProblem<G, L>& p) { return xi_scale(p); }
  static int inner_iterations(const Solution& s) { return s.inner_iterations; }
  static void set_inner_iterations(Solution& s, int n) { s.inner_iterations = n; }
};

namespace detail {

/// The shooting options of every solve on a continuation path: abandon hopeless ones early.
inline ShootingOptions path_shooting(const ContinuationOptions& options) {
  ShootingOptions path = options.shooting;
  path.no_progress_window = options.no_progress_window;
  return path;
}

/// The size of a result's terminal residual in the units of the convergence test.
template <class Problem, class Solution = typename ShootingFamily<Problem>::Solution>
double scaled_residual(const Problem& problem, const Solution& s) {
  if (s.trajectory.t.empty()) return std::numeric_limits<double>::infinity();
  return std::hypot(s.terminal_error, s.xi_terminal / ShootingFamily<Problem>::auxiliary_scale(problem));
}

/// Where a continuation path stopped.
struct PathEnd {
  double reached = 0;   ///< the parameter of the last accepted stage
  int stages = 0;
  bool complete = false;
  std::string why;      ///< empty when complete
};

/// Walks a scalar parameter from `from` to `to` along one solution branch; `make(s)` builds the
/// problem at parameter s. Predictor: the secant through the last two accepted solutions (the
/// previous solution for the first stage). Corrector: shooting from the prediction, abandoned
/// at once when the residual at the prediction exceeds max_stage_residual, and to
/// stage_tolerance except at the last stage. A stage is accepted when it converges *and* lands
/// within max_correction of the prediction (in the relative norm of `distance` below); otherwise
/// the increment is halved. On a smooth branch the
/// correction shrinks with the increment (quadratically after the first stage), so a small
/// enough stage is always accepted; a corrector that converges far from the prediction has
/// jumped to another branch (bench/README.md, "continuation acceptance"). Accumulates work into
/// `current`. Progress reports name the stage: "continuation in <parameter>, stage k at <parameter> = s".
template <class MakeProblem, class Problem = std::invoke_result_t<MakeProblem, double>,
          class Solution = typename ShootingFamily<Problem>::Solution>
PathEnd continue_parameter(const MakeProblem& make, double from, double to, Solution& current,
                           const ContinuationOptions& options, std::string_view parameter) {
  using Family = ShootingFamily<Problem>;
  using Velocity = typename Family::Velocity;
  using Auxiliary = typename Family::Auxiliary;
  PathEnd end{from, 0, false, {}};
  double increment = (to - from) / options.initial_stages;
  int sweeps = current.sweeps, iterations = Family::inner_iterations(current);
  const ShootingOptions path = path_shooting(options);
  // Relative sizes: v0 against the start's |v0| (or the target's geodesic speed), the auxiliary
  // against the start's (or the target's scale).
  const Problem target = make(to);
  const double v_ref = std::max(Family::velocity(current).norm(), Family::guess(target).norm());
  const double aux_ref = std::max(Family::auxiliary(current).norm(), Family::auxiliary_scale(target));
  const auto distance = [&](const Velocity& dv, const Auxiliary& da) {
    return std::hypot(v_ref > 0 ? dv.norm() / v_ref : dv.norm(), da.norm() / aux_ref);
  };
  std::optional<std::pair<Velocity, Auxiliary>> previous;  // the solution before `current`
  double previous_s = from;
  while (end.reached != to) {
    if (end.stages >= options.max_stages) {
      end.why = "max_stages = " + std::to_string(options.max_stages) + " reached";
      break;
    }
    if (path.monitor != nullptr && path.monitor->stop_requested()) {
      end.why = "stop requested";
      break;
    }
    const double next = std::abs(to - end.reached) <= std::abs(increment) ? to : end.reached + increment;
    ++end.stages;
    Velocity v_pred = Family::velocity(current);
    Auxiliary aux_pred = Family::auxiliary(current);
    if (previous) {
      const double ratio = (next - end.reached) / (end.reached - previous_s);
      v_pred += ratio * (Family::velocity(current) - previous->first);
      aux_pred += ratio * (Family::auxiliary(current) - previous->second);
    }
    ShootingOptions stage = path;
    const std::string name = std::string(parameter);
    const std::optional<SolveMonitor> named = SolveMonitor::staged(
        path.monitor, "continuation in " + name + ", stage " + std::to_string(end.stages) + " at " + name + " = " +
                          format_value(next));
    if (named) stage.monitor = &*named;
    stage.max_initial_residual = options.max_stage_residual;
    if (next != to) stage.tolerance = std::max(path.tolerance, options.stage_tolerance);
    Solution trial = Family::shoot(make(next), stage, v_pred, aux_pred);
    sweeps += trial.sweeps;
    iterations += Family::inner_iterations(trial);
    if (trial.converged() &&
        distance(Family::velocity(trial) - v_pred, Family::auxiliary(trial) - aux_pred) <= options.max_correction) {
      previous.emplace(Family::velocity(current), Family::auxiliary(current));
      previous_s = end.reached;
      end.reached = next;
      // The secant predictor's error grows as the square of the increment: aim the next stage at
      // half the residual limit, growing by at most 2 (1.5 when the stage gave no residual).
      const double r0 = trial.residual_history.empty() ? 0.0 : trial.residual_history.front();
      current = std::move(trial);
      increment *= r0 > 0 ? std::clamp(std::sqrt(options.max_stage_residual / 2 / r0), 0.5, 2.0) : 1.5;
    } else {
      increment /= 2;
      if (std::abs(increment) < options.min_increment * std::abs(to - from)) {
        end.why = "the increment fell below " + format_value(options.min_increment) +
                  " of the distance (a fold of the solution branch or a singularity near " +
                  format_value(end.reached) + ")";
        break;
      }
    }
  }
  current.sweeps = sweeps;
  Family::set_inner_iterations(current, iterations);
  end.complete = end.reached == to;
  return end;
}

/// The failure result of a continuation of `problem`: the better (smaller scaled residual) of
/// `direct` (an attempt on the requested problem, may be null; its trajectory is moved from, not
/// copied) and a solve of the requested problem from the last stage reached; status
/// ContinuationFailed (or Interrupted), all work counted.
template <class Problem, class Solution = typename ShootingFamily<Problem>::Solution>
Solution best_iterate(const Problem& problem, Solution* direct, const Solution* last_stage,
                      const ContinuationOptions& options, int sweeps, int iterations) {
  using Family = ShootingFamily<Problem>;
  Solution best;
  best.trajectory = {};
  double best_size = std::numeric_limits<double>::infinity();
  const auto consider = [&](Solution candidate) {
    const double size = scaled_residual(problem, candidate);
    if (size < best_size || best.trajectory.t.empty()) {
      best_size = size;
      best = std::move(candidate);
    }
  };
  if (direct != nullptr) consider(std::move(*direct));
  const bool stopped = options.shooting.monitor != nullptr && options.shooting.monitor->stop_requested();
  if (last_stage != nullptr && !stopped) {
    Solution from_stage =
        Family::shoot(problem, path_shooting(options), Family::velocity(*last_stage), Family::auxiliary(*last_stage));
    sweeps += from_stage.sweeps;
    iterations += Family::inner_iterations(from_stage);
    if (from_stage.converged()) {
      from_stage.sweeps = sweeps;
      Family::set_inner_iterations(from_stage, iterations);
      return from_stage;  // the last stage was close enough after all
    }
    consider(std::move(from_stage));
  }
  best.status = stopped ? Status::Interrupted : Status::ContinuationFailed;
  best.sweeps = sweeps;
  Family::set_inner_iterations(best, iterations);
  return best;
}

/// Continuation in T of any problem family (solve_continuation_in_T below; general/solve.hpp).
/// `failed_direct`, when not null, is moved from.
template <class Problem, class Solution = typename ShootingFamily<Problem>::Solution>
Solution continue_in_T(const Problem& problem, const ContinuationOptions& options,
                       std::optional<typename ShootingFamily<Problem>::Velocity> v0_guess,
                       std::optional<typename ShootingFamily<Problem>::Auxiliary> aux_guess,
                       Solution* failed_direct) {
  using Family = ShootingFamily<Problem>;
  using Velocity = typename Family::Velocity;
  using Auxiliary = typename Family::Auxiliary;
  if (failed_direct != nullptr && failed_direct->converged()) {
    throw std::invalid_argument("solve_continuation_in_T: failed_direct is a converged result; return it instead");
  }
  const auto start_time = std::chrono::steady_clock::now();
  const double h = problem.step();
  auto make = [&](double horizon) {
    Problem p = problem;
    p.T = horizon;
    p.N = std::max(1, static_cast<int>(std::lround(horizon / h)));
    if (horizon == problem.T) p.N = problem.N;
    return p;
  };
  const ShootingOptions path = path_shooting(options);
  double start = problem.T;
  // `first`: the last attempt from a guess; `direct`: the attempt at the full horizon. Solutions
  // are moved, never copied, where they may hold a long trajectory (N = 2e6: 0.3 GB).
  Solution first, direct;
  bool direct_is_first = false;  // the loop ended on the direct attempt, which is then `first`
  int sweeps = 0, iterations = 0;
  for (int halving = 0; halving <= options.max_halvings; ++halving, start /= 2) {
    if (halving == 0 && failed_direct != nullptr) {
      direct = std::move(*failed_direct);
      continue;
    }
    const Problem p = make(start);
    // The given guess is a velocity of the requested problem: at horizon T' the same path
    // needs T / T' times its speed.
    const Velocity v0 = v0_guess ? Velocity(*v0_guess * (problem.T / start)) : Family::guess(p);
    ShootingOptions start_options = path;
    const std::optional<SolveMonitor> named =
        SolveMonitor::staged(path.monitor, "continuation in T, start at T = " + format_value(start));
    if (named) start_options.monitor = &*named;
    if (halving > 0) start_options.max_initial_residual = options.max_start_residual;
    first = Family::shoot(p, start_options, v0, aux_guess && halving == 0 ? *aux_guess : Auxiliary(Auxiliary::Zero()));
    sweeps += first.sweeps;
    iterations += Family::inner_iterations(first);
    const bool done = first.converged() || first.status == Status::Interrupted;
    if (halving == 0 && done) direct_is_first = true;
    if (done) break;
    if (halving == 0) direct = std::move(first);
  }
  first.sweeps = sweeps;
  Family::set_inner_iterations(first, iterations);
  std::ostringstream path_text;
  Solution result;
  if (!first.converged()) {
    path_text << "no horizon down to T = " << format_value(start) << " converged from the "
              << (v0_guess ? "given" : "geodesic") << " guess";
    result = best_iterate(problem, direct_is_first ? &first : &direct, static_cast<const Solution*>(nullptr), options,
                          sweeps, iterations);
  } else if (start == problem.T) {
    path_text << (v0_guess || aux_guess ? "direct from the given guess" : "direct from the geodesic guess");
    result = std::move(first);
  } else {
    path_text << "continued in T from T = " << format_value(start);
    result = std::move(first);
    const PathEnd end = continue_parameter(make, start, problem.T, result, options, "T");
    path_text << " (" << end.stages << " stages)";
    if (!end.complete) {
      path_text << "; stopped at T = " << format_value(end.reached) << ": " << end.why;
      result = best_iterate(problem, &direct, &result, options, result.sweeps, Family::inner_iterations(result));
    }
  }
  result.method = Method::Shooting;
  result.branch = result.converged() ? path_text.str() : "failed: " + path_text.str();
  result.message = "continuation in T: " + path_text.str() + "; " + std::to_string(result.sweeps) +
                   " sweeps in all; the returned iterate: " + result.message;
  result.solve_time_s = seconds_since(start_time);
  return result;
}

}  // namespace detail

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
  return detail::continue_in_T(problem, options, v0_guess, xi0_guess, direct ? &*direct : nullptr);
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
  return detail::continue_in_T(problem, options, v0_guess, xi0_guess, &failed_direct);
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
  const auto start_time = std::chrono::steady_clock::now();
  auto make = [&](double lambda) {
    TransportedProblem<G, L> p = problem;
    p.lambda = lambda;
    return p;
  };
  TransportedSolution<G> result = solve_continuation_in_T(make(lambda_start), options);
  std::ostringstream path_text;
  if (!result.converged()) {
    path_text << "no solution at lambda = " << format_value(lambda_start) << " (" << result.branch << ")";
    const bool same = lambda_start == problem.lambda;  // then that attempt was of the requested problem
    result = detail::best_iterate(problem, same ? &result : nullptr, static_cast<const TransportedSolution<G>*>(nullptr),
                                  options, result.sweeps, result.inner_iterations);
  } else {
    path_text << "continued in lambda from lambda = " << format_value(lambda_start) << " [" << result.branch << "]";
    const detail::PathEnd end = detail::continue_parameter(make, lambda_start, problem.lambda, result, options, "lambda");
    path_text << " (" << end.stages << " stages)";
    if (!end.complete) {
      path_text << "; stopped at lambda = " << format_value(end.reached) << ": " << end.why;
      result = detail::best_iterate(problem, static_cast<TransportedSolution<G>*>(nullptr), &result, options,
                                    result.sweeps, result.inner_iterations);
    }
  }
  result.method = Method::Shooting;
  result.branch = result.converged() ? path_text.str() : "failed: " + path_text.str();
  result.message = "continuation in lambda: " + path_text.str() + "; " + std::to_string(result.sweeps) +
                   " sweeps in all; the returned iterate: " + result.message;
  result.solve_time_s = detail::seconds_since(start_time);
  return result;
}

}  // namespace cartan::transported
