// The continuation paths of every problem family (solvers/continuation.hpp), compiled once: the
// family is a ShootingPath, its solutions PathResults; sizes are the family's own norms.
#include "cartan/solvers/continuation.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <sstream>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/monitor.hpp"

namespace cartan::solvers {

namespace {

int iterations_of(const ShootingPath& path, const PathResult& r) {
  return path.sums_inner_iterations() ? r.core().inner_iterations : 0;
}

void set_work(const ShootingPath& path, PathResult& r, int sweeps, int iterations) {
  r.core().sweeps = sweeps;
  if (path.sums_inner_iterations()) r.core().inner_iterations = iterations;
}

}  // namespace

PathEnd continue_parameter(const ShootingPath& family, double from, double to, PathResultPtr& current,
                           const ContinuationOptions& options, std::string_view parameter) {
  PathEnd end{from, 0, false, {}};
  double increment = (to - from) / options.initial_stages;
  int sweeps = current->core().sweeps, iterations = iterations_of(family, *current);
  const ShootingOptions path = path_shooting(options);
  // Relative sizes: v0 against the start's |v0| (or the target's geodesic speed), the auxiliary
  // against the start's (or the target's scale).
  const double v_ref = std::max(family.velocity_norm(current->velocity()), family.velocity_norm(family.guess(to)));
  const double aux_ref = std::max(family.auxiliary_norm(current->auxiliary()), family.auxiliary_scale(to));
  const auto distance = [&](const Eigen::VectorXd& dv, const Eigen::VectorXd& da) {
    const double v = family.velocity_norm(dv);
    return std::hypot(v_ref > 0 ? v / v_ref : v, family.auxiliary_norm(da) / aux_ref);
  };
  std::optional<Unknowns> previous;  // the solution before `current`
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
    Unknowns now{current->velocity(), current->auxiliary()};
    Eigen::VectorXd v_pred = now.velocity, aux_pred = now.auxiliary;
    if (previous) {  // element by element, as the typed arithmetic (one-core.md, R2)
      const double ratio = (next - end.reached) / (end.reached - previous_s);
      v_pred += ratio * (now.velocity - previous->velocity);
      aux_pred += ratio * (now.auxiliary - previous->auxiliary);
    }
    ShootingOptions stage = path;
    const std::string name = std::string(parameter);
    const std::optional<SolveMonitor> named = SolveMonitor::staged(
        path.monitor, "continuation in " + name + ", stage " + std::to_string(end.stages) + " at " + name + " = " +
                          format_value(next));
    if (named) stage.monitor = &*named;
    stage.max_initial_residual = options.max_stage_residual;
    if (next != to) stage.tolerance = std::max(path.tolerance, options.stage_tolerance);
    PathResultPtr trial = family.shoot(next, stage, v_pred, aux_pred);
    sweeps += trial->core().sweeps;
    iterations += iterations_of(family, *trial);
    if (trial->core().converged() &&
        distance(trial->velocity() - v_pred, trial->auxiliary() - aux_pred) <= options.max_correction) {
      previous = std::move(now);
      previous_s = end.reached;
      end.reached = next;
      // The secant predictor's error grows as the square of the increment: aim the next stage at
      // half the residual limit, growing by at most 2 (1.5 when the stage gave no residual).
      const std::vector<double>& history = trial->core().residual_history;
      const double r0 = history.empty() ? 0.0 : history.front();
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
  set_work(family, *current, sweeps, iterations);
  end.complete = end.reached == to;
  return end;
}

PathResultPtr best_iterate(const ShootingPath& family, double requested, PathResultPtr direct,
                           const std::optional<Unknowns>& last_stage, const ContinuationOptions& options, int sweeps,
                           int iterations) {
  PathResultPtr best = family.empty();
  double best_size = std::numeric_limits<double>::infinity();
  const auto consider = [&](PathResultPtr candidate) {
    const double size = candidate->has_trajectory()
                            ? scaled_residual(candidate->core(), family.auxiliary_scale(requested))
                            : std::numeric_limits<double>::infinity();
    if (size < best_size || !best->has_trajectory()) {
      best_size = size;
      best = std::move(candidate);
    }
  };
  if (direct != nullptr) consider(std::move(direct));
  const bool stopped = options.shooting.monitor != nullptr && options.shooting.monitor->stop_requested();
  if (last_stage && !stopped) {
    PathResultPtr from_stage = family.shoot(requested, path_shooting(options), last_stage->velocity, last_stage->auxiliary);
    sweeps += from_stage->core().sweeps;
    iterations += iterations_of(family, *from_stage);
    if (from_stage->core().converged()) {
      set_work(family, *from_stage, sweeps, iterations);
      return from_stage;  // the last stage was close enough after all
    }
    consider(std::move(from_stage));
  }
  best->core().status = stopped ? Status::Interrupted : Status::ContinuationFailed;
  set_work(family, *best, sweeps, iterations);
  return best;
}

PathResultPtr continue_in_T(const ShootingPath& family, double T, const ContinuationOptions& options,
                            const std::optional<Eigen::VectorXd>& velocity_guess,
                            const std::optional<Eigen::VectorXd>& auxiliary_guess, PathResultPtr failed_direct) {
  if (failed_direct != nullptr && failed_direct->core().converged()) {
    throw std::invalid_argument("solve_continuation_in_T: failed_direct is a converged result; return it instead");
  }
  const auto start_time = std::chrono::steady_clock::now();
  const ShootingOptions path = path_shooting(options);
  double start = T;
  // `first`: the last attempt from a guess; `direct`: the attempt at the full horizon. Results
  // are moved, never copied, where they may hold a long trajectory (N = 2e6: 0.3 GB).
  PathResultPtr first = family.empty(), direct = family.empty();
  bool direct_is_first = false;  // the loop ended on the direct attempt, which is then `first`
  int sweeps = 0, iterations = 0;
  for (int halving = 0; halving <= options.max_halvings; ++halving, start /= 2) {
    if (halving == 0 && failed_direct != nullptr) {
      direct = std::move(failed_direct);
      continue;
    }
    // The given guess is a velocity of the requested problem: at horizon T' the same path
    // needs T / T' times its speed.
    const Eigen::VectorXd v0 = velocity_guess ? Eigen::VectorXd(*velocity_guess * (T / start)) : family.guess(start);
    ShootingOptions start_options = path;
    const std::optional<SolveMonitor> named =
        SolveMonitor::staged(path.monitor, "continuation in T, start at T = " + format_value(start));
    if (named) start_options.monitor = &*named;
    if (halving > 0) start_options.max_initial_residual = options.max_start_residual;
    first = family.shoot(start, start_options, v0,
                         auxiliary_guess && halving == 0 ? *auxiliary_guess : family.zero_auxiliary());
    sweeps += first->core().sweeps;
    iterations += iterations_of(family, *first);
    const bool done = first->core().converged() || first->core().status == Status::Interrupted;
    if (halving == 0 && done) direct_is_first = true;
    if (done) break;
    if (halving == 0) {
      direct = std::move(first);
      first = family.empty();
    }
  }
  set_work(family, *first, sweeps, iterations);
  std::ostringstream path_text;
  PathResultPtr result;
  if (!first->core().converged()) {
    path_text << "no horizon down to T = " << format_value(start) << " converged from the "
              << (velocity_guess ? "given" : "geodesic") << " guess";
    result = best_iterate(family, T, direct_is_first ? std::move(first) : std::move(direct), std::nullopt, options, sweeps,
                          iterations);
  } else if (start == T) {
    path_text << (velocity_guess || auxiliary_guess ? "direct from the given guess" : "direct from the geodesic guess");
    result = std::move(first);
  } else {
    path_text << "continued in T from T = " << format_value(start);
    result = std::move(first);
    const PathEnd end = continue_parameter(family, start, T, result, options, "T");
    path_text << " (" << end.stages << " stages)";
    if (!end.complete) {
      path_text << "; stopped at T = " << format_value(end.reached) << ": " << end.why;
      const Unknowns last{result->velocity(), result->auxiliary()};
      const int path_sweeps = result->core().sweeps, path_iterations = iterations_of(family, *result);
      result = best_iterate(family, T, std::move(direct), last, options, path_sweeps, path_iterations);
    }
  }
  ResultCore& core = result->core();
  core.method = Method::Shooting;
  core.branch = core.converged() ? path_text.str() : "failed: " + path_text.str();
  core.message = "continuation in T: " + path_text.str() + "; " + std::to_string(core.sweeps) +
                 " sweeps in all; the returned iterate: " + core.message;
  core.solve_time_s = seconds_since(start_time);
  return result;
}

PathResultPtr continue_in_parameter(const ShootingPath& family, double from, double to, PathResultPtr start,
                                    const ContinuationOptions& options, std::string_view parameter,
                                    std::chrono::steady_clock::time_point started) {
  std::ostringstream path_text;
  PathResultPtr result = std::move(start);
  const int sweeps = result->core().sweeps, iterations = iterations_of(family, *result);
  if (!result->core().converged()) {
    path_text << "no solution at " << parameter << " = " << format_value(from) << " (" << result->core().branch << ")";
    const bool same = from == to;  // then that attempt was of the requested problem
    result = best_iterate(family, to, same ? std::move(result) : nullptr, std::nullopt, options, sweeps, iterations);
  } else {
    path_text << "continued in " << parameter << " from " << parameter << " = " << format_value(from) << " ["
              << result->core().branch << "]";
    const PathEnd end = continue_parameter(family, from, to, result, options, parameter);
    path_text << " (" << end.stages << " stages)";
    if (!end.complete) {
      path_text << "; stopped at " << parameter << " = " << format_value(end.reached) << ": " << end.why;
      const Unknowns last{result->velocity(), result->auxiliary()};
      const int path_sweeps = result->core().sweeps, path_iterations = iterations_of(family, *result);
      result = best_iterate(family, to, nullptr, last, options, path_sweeps, path_iterations);
    }
  }
  ResultCore& core = result->core();
  core.method = Method::Shooting;
  core.branch = core.converged() ? path_text.str() : "failed: " + path_text.str();
  core.message = "continuation in " + std::string(parameter) + ": " + path_text.str() + "; " +
                 std::to_string(core.sweeps) + " sweeps in all; the returned iterate: " + core.message;
  core.solve_time_s = seconds_since(started);
  return result;
}

}  // namespace cartan::solvers
