#pragma once
// The options and guesses of the library's solve (transported/solve.hpp), in a light header
// for the CLI and the Python module.

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cartan/errors.hpp"
#include "cartan/monitor.hpp"
#include "cartan/status.hpp"
#include "cartan/transported/method.hpp"
#include "cartan/scheme_order.hpp"
#include "cartan/transported/trajectory.hpp"

namespace cartan::transported {

using ::cartan::SchemeOrder;  // scheme_order.hpp: the vocabulary of both stacks

/// The single-shooting solver's options (shooting.hpp; also the general shooting's).
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
  std::optional<int> max_nodes;        ///< collocation only (default transported::kTransportedMaxNodes)
  /// Seconds the whole call may take (every method and attempt): the running method stops (polled
  /// once per iteration and inside sweeps) early enough for the work after a stop, and the result
  /// has status time-limit. Empty: no limit.
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
    if (samples < 0 || samples == 1) {
      throw_invalid(where, "samples", std::to_string(samples),
                    "must be 0 (the final mesh) or at least 2 (uniform times on [0, T])");
    }
    if (time_limit && !(std::isfinite(*time_limit) && *time_limit > 0)) {
      throw_invalid(where, "time_limit", format_value(*time_limit), "must be a positive number of seconds");
    }
    if (max_nodes && method != Method::Collocation) {
      throw_invalid(where, "max_nodes", std::to_string(*max_nodes), "applies to method collocation only, not " + m);
    }
  }
};

/// The options of one call from `start`: time_limit becomes the monitor's deadline.
inline SolveOptions with_deadline(const SolveOptions& options, std::chrono::steady_clock::time_point start) {
  SolveOptions timed = options;
  if (options.time_limit) {
    timed.monitor = options.monitor.with_deadline(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                              std::chrono::duration<double>(*options.time_limit)));
  }
  return timed;
}

/// A solve stopped by the deadline of `timed` (with_deadline) has status time-limit, not interrupted.
inline void apply_time_limit(const SolveOptions& timed, Status& status, std::string& message) {
  if (status == Status::Interrupted && timed.monitor.deadline_passed()) {
    status = Status::TimeLimit;
    message = "time limit of " + format_value(*timed.time_limit) + " s reached; " + message;
  }
}

/// Optional starting points: v0 and xi0, or a whole trajectory (t from 0 to T, g, v and xi at
/// every entry; mu is not read). A trajectory supplies v0 and xi0 to the shooting methods and
/// the whole guess to collocation.
template <groups::LieGroup G>
struct SolveGuess {
  std::optional<groups::TangentOf<G>> v0;
  std::optional<groups::CovectorOf<G>> xi0;
  std::optional<TransportedTrajectory<G>> trajectory;

  bool empty() const { return !v0 && !xi0 && !trajectory; }
  /// The guess of v(0) and of xi(0): given directly, or the trajectory's first entry; none if neither.
  std::optional<groups::TangentOf<G>> start_v0() const { return v0 ? v0 : trajectory ? std::optional(trajectory->v.front()) : std::nullopt; }
  std::optional<groups::CovectorOf<G>> start_xi0() const {
    return xi0 ? xi0 : trajectory ? std::optional(trajectory->xi.front()) : std::nullopt;
  }

  /// Throws std::invalid_argument for non-finite values, both v0/xi0 and a trajectory, or a
  /// trajectory that is not on [0, T] with strictly increasing times and rows of equal count.
  void validate(double T) const {
    constexpr std::string_view where = "SolveGuess";
    if (v0) require_finite(*v0, where, "v0");
    if (xi0) require_finite(*xi0, where, "xi0");
    if (!trajectory) return;
    if (v0 || xi0) throw std::invalid_argument("SolveGuess: give v0/xi0 or a trajectory, not both");
    trajectory->validate(T, where, false, 1e-12);
  }
};

namespace detail {

/// Seconds since `start` (steady clock).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace detail

/// Seconds spent in f().
template <class F>
auto timed(double& seconds, F&& f) {
  const auto start = std::chrono::steady_clock::now();
  auto out = f();
  seconds = detail::seconds_since(start);
  return out;
}

}  // namespace cartan::transported
