#pragma once
// The options of every transported-velocity solve, whichever kernel runs (DESIGN.md, layer
// "principle"): one shooting, a continuation path, a whole solve; the deadline of a call. A light
// header for the CLI, the Python module and both kernels.

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cartan/errors.hpp"
#include "cartan/monitor.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/scheme_order.hpp"
#include "cartan/status.hpp"

namespace cartan {

/// Throws std::invalid_argument unless samples is 0 or at least 2 (as `cartan solve --samples`).
inline void check_samples(int samples, std::string_view where = "collocation") {
  if (samples < 0 || samples == 1) {
    throw_invalid(where, "samples", std::to_string(samples),
                  "must be 0 (the final mesh) or at least 2 (uniform times on [0, T])");
  }
}

/// The options of one shooting (methods/lie_group/shooting.hpp, methods/manifold/shooting.hpp).
struct ShootingOptions {
  SchemeOrder order = SchemeOrder::First;
  double tolerance = 1e-10;     ///< on |(log(gT^{-1} g_N), xi_N / xi_scale)| (dimensionless)
  int max_iterations = 100;     ///< Levenberg–Marquardt iterations
  bool analytic_jacobian = true;
  int no_progress_window = 0;   ///< > 0: abandon when |r| has not halved in this many iterations
  /// Abandon at once when the scaled |r| of the guess exceeds this (continuation stages).
  double max_initial_residual = std::numeric_limits<double>::infinity();
  const SolveMonitor* monitor = nullptr;  ///< progress and stop requests; may be null

  void validate() const {
    require_finite(tolerance, "ShootingOptions", "tolerance");
    if (!(tolerance > 0)) throw_invalid("ShootingOptions", "tolerance", format_value(tolerance), "must be positive");
    if (max_iterations < 1) {
      throw_invalid("ShootingOptions", "max_iterations", std::to_string(max_iterations), "must be at least 1");
    }
    if (!(max_initial_residual > 0)) {
      throw_invalid("ShootingOptions", "max_initial_residual", format_value(max_initial_residual), "must be positive");
    }
  }
};

/// A continuation path's (methods/lie_group/continuation.hpp, solvers/continuation.hpp).
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

/// The shooting options of every solve on a continuation path: abandon hopeless ones early.
inline ShootingOptions path_shooting(const ContinuationOptions& options) {
  ShootingOptions path = options.shooting;
  path.no_progress_window = options.no_progress_window;
  return path;
}

struct SolveOptions {
  Method method = Method::Auto;
  /// shooting: how to reach a problem that fails from the guess; collocation: where to start
  /// when Newton from the geodesic guess fails (from the order-2 shooting solution so found).
  Continuation continuation = Continuation::None;
  SchemeOrder order = SchemeOrder::First;
  /// Shooting and multiple shooting: on |(log(gT^{-1} g_N), xi_N / xi_scale)| (radians and a
  /// relative xi, shooting.hpp); two-level: the outer change of xi relative to xi_scale (its inner
  /// loop works to 1e-13); collocation: the relative RMS residual on every interval.
  double tol = kDefaultTol;
  int max_iterations = kDefaultMaxIterations;
  std::optional<int> segments;         ///< multiple shooting only (default: about 100 steps each, at most 16)
  std::optional<double> lambda_start;  ///< continuation in lambda only (default 0)
  int samples = 0;                     ///< collocation only: output at this many uniform times (0: the final mesh)
  std::optional<int> max_nodes;        ///< collocation only (default kDefaultMaxNodes)
  /// Seconds the whole call may take (every method and attempt): the running method stops (polled
  /// once per iteration, inside sweeps, dense factorisations and difference Jacobians) early enough
  /// for the work after a stop, and the result has status time-limit. Empty: no limit.
  std::optional<double> time_limit;
  SolveMonitor monitor;                ///< progress reports and stop requests

  /// Throws std::invalid_argument naming the first bad or inapplicable option.
  void validate() const {
    constexpr std::string_view where = "SolveOptions";
    require_finite(tol, where, "tol");
    require_reachable_tolerance(tol, where);  // every method refuses what none can reach
    if (max_iterations < 1) throw_invalid(where, "max_iterations", std::to_string(max_iterations), "must be at least 1");
    require_scheme_order(order, where);
    const std::string m = std::string(to_string(method));
    if (order != SchemeOrder::First && method == Method::Variational) {
      throw_invalid(where, "order", std::to_string(static_cast<int>(order)),
                    "applies to the schemes of the shooting methods, not to variational (second order by construction)");
    }
    if (segments && method != Method::MultipleShooting) {
      throw_invalid(where, "segments", std::to_string(*segments), "applies to method multiple-shooting only, not " + m);
    }
    if (segments && *segments < 1) throw_invalid(where, "segments", std::to_string(*segments), "must be at least 1");
    if (continuation != Continuation::None && method != Method::Shooting && method != Method::Collocation) {
      throw_invalid(where, "continuation", std::string(to_string(continuation)),
                    "applies to methods shooting and collocation only, not " + m);
    }
    if (lambda_start && continuation != Continuation::Lambda) {
      throw_invalid(where, "lambda_start", format_value(*lambda_start), "applies to continuation lambda only");
    }
    if (lambda_start) require_finite(*lambda_start, where, "lambda_start");
    if (samples != 0 && method != Method::Collocation) {
      throw_invalid(where, "samples", std::to_string(samples), "applies to method collocation only, not " + m);
    }
    check_samples(samples, where);
    if (time_limit && !(std::isfinite(*time_limit) && *time_limit > 0)) {
      throw_invalid(where, "time_limit", format_value(*time_limit), "must be a positive number of seconds");
    }
    if (max_nodes && method != Method::Collocation) {
      throw_invalid(where, "max_nodes", std::to_string(*max_nodes), "applies to method collocation only, not " + m);
    }
  }
};

/// The options as the CLI's flags and Python's keywords give them: the method and the
/// continuation by their words, the order as a number, the defaults the library's. solve_options
/// translates them, once for every caller (`cartan solve`, cartan.solve, cartan.solve_general).
struct OptionWords {
  std::string method = "auto";        ///< a Method word
  std::string continuation = "none";  ///< a Continuation word
  int order = 1;
  double tol = kDefaultTol;
  int max_iterations = kDefaultMaxIterations;
  std::optional<int> segments;
  std::optional<double> lambda_start;
  int samples = 0;
  std::optional<int> max_nodes;
  std::optional<double> time_limit;
};

/// The SolveOptions of `words` (without a monitor). Throws std::invalid_argument "<where>:
/// <name> = <value> is not one of: ..." for an unknown word and "<where>: order = <k> must be 1
/// or 2" for another order; the options' other checks are SolveOptions::validate's, which every
/// solve runs.
SolveOptions solve_options(const OptionWords& words, std::string_view where);

/// The options of one call from `start`: time_limit becomes the monitor's deadline.
inline SolveOptions with_deadline(const SolveOptions& options, std::chrono::steady_clock::time_point start) {
  SolveOptions timed = options;
  if (options.time_limit) {
    timed.monitor = options.monitor.with_deadline(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                              std::chrono::duration<double>(*options.time_limit)));
  }
  return timed;
}

/// A solve stopped by the deadline of `timed` (with_deadline) has status time-limit, not interrupted,
/// and so has every attempt its branch names (the default strategy's stages said "interrupted").
inline void apply_time_limit(const SolveOptions& timed, Status& status, std::string& message, std::string& branch) {
  if (status == Status::Interrupted && timed.monitor.deadline_passed()) {
    status = Status::TimeLimit;
    message = "time limit of " + format_value(*timed.time_limit) + " s reached; " + message;
    const std::string_view from = to_string(Status::Interrupted), to = to_string(Status::TimeLimit);
    for (std::size_t at = branch.find(from); at != std::string::npos; at = branch.find(from, at + to.size())) {
      branch.replace(at, from.size(), to);
    }
  }
}

/// Seconds since `start` (steady clock).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Seconds spent in f().
template <class F>
auto timed(double& seconds, F&& f) {
  const auto start = std::chrono::steady_clock::now();
  auto out = f();
  seconds = seconds_since(start);
  return out;
}

}  // namespace cartan
