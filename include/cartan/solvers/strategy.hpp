#pragma once
// The default strategy (Method::Auto) of every kernel, compiled once (src/solvers/strategy.cpp):
// what to try, in which order, on what condition, and the words of the result. A kernel (the
// Lie-group one, methods/lie_group/solve.hpp; the general one and the Lie-group kernel inside the
// general solve, methods/manifold/solve.hpp) says what it can do and runs each method; the strategy
// decides. The steps:
//   1. shooting from the guess (the geodesic guess by default), abandoned once |r| stops halving
//      (within the kernel's window);
//   2. continuation in T, unless the kernel's problem is invariant under a rescaling of time
//      (then a shorter horizon is the same problem) or N is too small to halve T;
//   3. continuation in lambda from lambda = 0, then from 1 (the flat connections), where the
//      kernel's connection is Cartan–Schouten given by its lambda;
//   4. collocation of the continuous problem where the kernel has it, then shooting the discrete
//      scheme from the collocation solution, so that the result is on the N steps;
//   5. multiple shooting from the guess, where the kernel has it.
// The first success is the result, its branch naming the whole path ("continuation in T (...),
// after shooting failed"); when every attempt fails, the best iterate of the requested problem
// with status StrategyFailed (solvers::Attempts).

#include <optional>

#include "cartan/monitor.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/solvers/continuation.hpp"

namespace cartan::solvers {

/// What the default strategy asks of a kernel. Every method's result is a complete result of the
/// requested problem (continuation's: of the requested problem at the end of its path).
class StrategyKernel {
 public:
  virtual ~StrategyKernel() = default;

  /// A result without trajectory (what a strategy whose attempts had none returns).
  virtual PathResultPtr empty() const = 0;
  /// The unit of the requested problem's auxiliary (xi or Xi), to size failed attempts.
  virtual double auxiliary_scale() const = 0;
  /// Whether the caller gave a guess (v0, an auxiliary or a trajectory).
  virtual bool guessed() const = 0;
  virtual int steps() const = 0;  ///< N
  /// Whether the problem at horizon cT is the problem at T with time rescaled (a purely kinetic
  /// Lagrangian): continuation in T cannot help then.
  virtual bool time_rescaling_invariant() const = 0;
  /// The lambda of the kernel's Cartan–Schouten connection where it continues in lambda.
  virtual std::optional<double> lambda() const = 0;
  virtual bool has_collocation() const = 0;
  virtual bool has_multiple_shooting() const = 0;
  /// Step 1's no-progress window: iterations without |r| halving before the first shooting is
  /// abandoned for continuation in T (the kernel's: its Levenberg–Marquardt may stall longer
  /// before it descends).
  virtual int first_shooting_window() const = 0;

  /// Shooting from the guess (the geodesic guess without one).
  virtual PathResultPtr shoot(const ShootingOptions& options) = 0;
  /// Shooting from the unknowns of `start`, a result of collocate().
  virtual PathResultPtr shoot_from(const ShootingOptions& options, const PathResult& start) = 0;
  /// Continuation in T from the guess; `failed_direct`, a failed shoot() with the same shooting
  /// options, is the path's first attempt at the full horizon (not repeated); null: the path
  /// makes its own.
  virtual PathResultPtr continue_in_T(const ContinuationOptions& options, PathResultPtr failed_direct) = 0;
  /// Continuation in lambda from the solution at lambda = `start` (no guess).
  virtual PathResultPtr continue_in_lambda(const ContinuationOptions& options, double start) = 0;
  /// Collocation of the continuous problem (the options' method is Collocation), its solution
  /// sampled at `samples` uniform times.
  virtual PathResultPtr collocate(const SolveOptions& options, int samples) = 0;
  /// Multiple shooting from the guess (the options' segments), reporting to `stage`.
  virtual PathResultPtr multiple_shoot(const SolveOptions& options, const SolveMonitor& stage) = 0;
  /// The two-level scheme from the guess's v0, reporting to `stage` (the Lie-group kernel's).
  virtual PathResultPtr two_level(const SolveOptions& options, const SolveMonitor& stage);
  /// Newton on the discrete Euler–Lagrange equations from the guess trajectory or the geodesic
  /// path, reporting to `stage` (the Lie-group solve's); names its own branch.
  virtual PathResultPtr variational(const SolveOptions& options, const SolveMonitor& stage);
};

/// The branch of a shooting from the kernel's guess: "direct from the given guess" or "direct
/// from the geodesic guess".
inline const char* direct_branch(const StrategyKernel& kernel) {
  return kernel.guessed() ? "direct from the given guess" : "direct from the geodesic guess";
}

/// The default strategy (header comment) on `kernel` under `options` (with their deadline).
PathResultPtr default_strategy(StrategyKernel& kernel, const SolveOptions& options);

/// The method `options` ask for on `kernel`, once the caller has checked that the kernel has it
/// (each solve's validate: its refusals name the kernel): Auto is default_strategy; Shooting is
/// shooting from the guess, or with Continuation::T continuation in T from the guess (its first
/// stage the path's: docs/design/one-core.md D7), with Lambda continuation in lambda from
/// lambda_start; the other methods the kernel's own. Stages of the options' monitor are named
/// after the method ("shooting", "multiple shooting", "two-level", "collocation", "variational").
/// Throws std::logic_error for a method the kernel lacks.
PathResultPtr run_method(StrategyKernel& kernel, const SolveOptions& options);

}  // namespace cartan::solvers
