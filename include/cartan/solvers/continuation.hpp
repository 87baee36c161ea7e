#pragma once
// Continuation paths, written once for every problem family with shooting (the Lie-group kernel's
// TransportedProblem, transported/continuation.hpp; the general GeneralProblem, general/solve.hpp;
// the Lie-group kernel inside the general solve, general/lie_kernel.hpp). ShootingFamily<Problem>
// says how to shoot and where the unknowns (a velocity and an auxiliary: (v0, xi0) or (v0, Xi0))
// live in a solution; the path itself (docs/paper-notes.md#erratum-4):
//  * in T: halve the horizon until shooting from the guess converges, then lengthen it step by
//    step (same step size h, so N scales with T), each solve starting from the previous
//    unknowns; a failed stage halves the increment;
//  * any scalar parameter (lambda: transported/continuation.hpp) by continue_parameter.
// A failed path returns the best iterate *of the requested problem*, never a stage's trajectory
// at another T or lambda, and its message says where the path stopped.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "cartan/errors.hpp"
#include "cartan/monitor.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/status.hpp"

namespace cartan::solvers {

/// How continuation drives shooting on one problem family (header comment).
template <class Problem>
struct ShootingFamily;

namespace detail {

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

}  // namespace cartan::solvers
