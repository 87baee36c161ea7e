// The default strategy of every kernel (solvers/strategy.hpp), compiled once.
#include "cartan/solvers/strategy.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "cartan/errors.hpp"
#include "cartan/solvers/attempts.hpp"

namespace cartan::solvers {

namespace {

/// The shooting every step runs (the options' order, tolerance and iterations), reporting to `stage`.
ShootingOptions shooting_options(const SolveOptions& options, const SolveMonitor& stage) {
  return {.order = options.order, .tolerance = options.tol, .max_iterations = options.max_iterations, .monitor = &stage};
}

}  // namespace

PathResultPtr default_strategy(StrategyKernel& kernel, const SolveOptions& options) {
  Attempts attempts(kernel.empty(), [&kernel] { return kernel.auxiliary_scale(); });
  const auto stopped = [&] { return options.monitor.stop_requested(); };
  const auto finish = [&](bool solved) { return attempts.finish(solved, !solved && stopped()); };

  // 1. Shooting from the guess, abandoned when it makes no progress.
  constexpr int kMinStepsToHalve = 16;
  const bool halve_horizon = !kernel.time_rescaling_invariant() && kernel.steps() >= kMinStepsToHalve;  // step 2
  PathResultPtr direct_attempt;
  {
    const SolveMonitor stage = options.monitor.stage("shooting");
    ShootingOptions s = shooting_options(options, stage);
    s.no_progress_window = kernel.first_shooting_window();
    PathResultPtr r = kernel.shoot(s);
    r->core().branch = direct_branch(kernel);
    if (halve_horizon && !r->core().converged() && !stopped()) direct_attempt = r->clone();  // step 2 starts from it
    if (attempts.attempt("shooting", std::move(r))) return finish(true);
  }
  // 2. Continuation in T where a shorter horizon is an easier problem; its first stage would
  // repeat step 1 exactly (same start, same shooting options), so it reuses it.
  if (halve_horizon && !stopped()) {
    const SolveMonitor stage = options.monitor.stage("shooting");
    const ContinuationOptions c{.shooting = shooting_options(options, stage)};
    if (attempts.attempt("continuation in T", kernel.continue_in_T(c, std::move(direct_attempt)))) return finish(true);
  }
  // 3. Continuation in lambda from the flat connections.
  if (const std::optional<double> lambda = kernel.lambda()) {
    for (const double start : {0.0, 1.0}) {
      if (*lambda == start || stopped()) continue;
      const SolveMonitor stage = options.monitor.stage("shooting");
      const ContinuationOptions c{.shooting = shooting_options(options, stage)};
      if (attempts.attempt("continuation in lambda from " + format_value(start), kernel.continue_in_lambda(c, start))) {
        return finish(true);
      }
    }
  }
  // 4. Collocation of the continuous problem, then the discrete scheme from its solution.
  if (kernel.has_collocation() && !stopped()) {
    SolveOptions c = options;
    c.method = Method::Collocation;
    PathResultPtr continuous = kernel.collocate(c, kernel.steps() + 1);
    if (continuous->core().converged()) {
      const SolveMonitor stage = options.monitor.stage("shooting");
      PathResultPtr polished = kernel.shoot_from(shooting_options(options, stage), *continuous);
      attempts.add_sweeps(continuous->core().sweeps);
      polished->core().branch = "from the collocation solution";
      if (attempts.attempt("shooting", std::move(polished))) return finish(true);
      attempts.forget_last_failure();
      continuous->core().branch = "of the continuous problem; shooting the discrete scheme from it failed";
    }
    // A failed collocation is never the best iterate: its boundary conditions hold by construction,
    // so its terminal residual is about zero however large its defect inside.
    if (attempts.attempt("collocation", std::move(continuous), /*requested_problem=*/false)) return finish(true);
  }
  // 5. Multiple shooting from the guess.
  if (kernel.has_multiple_shooting() && !stopped() && kernel.steps() >= 2) {
    const SolveMonitor stage = options.monitor.stage("multiple shooting");
    if (attempts.attempt("multiple shooting", kernel.multiple_shoot(options, stage))) return finish(true);
  }
  return finish(false);
}

PathResultPtr StrategyKernel::two_level(const SolveOptions&, const SolveMonitor&) {
  throw std::logic_error("solvers::StrategyKernel: the two-level scheme is not a method of this kernel");
}

PathResultPtr StrategyKernel::variational(const SolveOptions&, const SolveMonitor&) {
  throw std::logic_error("solvers::StrategyKernel: the variational method is not a method of this kernel");
}

PathResultPtr run_method(StrategyKernel& kernel, const SolveOptions& options) {
  switch (options.method) {
    case Method::Auto: return default_strategy(kernel, options);
    case Method::Shooting: {
      const SolveMonitor stage = options.monitor.stage("shooting");
      const ContinuationOptions c{.shooting = shooting_options(options, stage)};
      switch (options.continuation) {
        case Continuation::T: return kernel.continue_in_T(c, nullptr);
        case Continuation::Lambda: return kernel.continue_in_lambda(c, options.lambda_start.value_or(0.0));
        case Continuation::None: break;
      }
      PathResultPtr r = kernel.shoot(c.shooting);
      r->core().branch = direct_branch(kernel);
      return r;
    }
    case Method::MultipleShooting: {
      const SolveMonitor stage = options.monitor.stage("multiple shooting");
      return kernel.multiple_shoot(options, stage);
    }
    case Method::TwoLevel: {
      const SolveMonitor stage = options.monitor.stage("two-level");
      PathResultPtr r = kernel.two_level(options, stage);
      r->core().branch = direct_branch(kernel);
      return r;
    }
    case Method::Collocation: return kernel.collocate(options, options.samples);
    case Method::Variational: {
      const SolveMonitor stage = options.monitor.stage("variational");
      return kernel.variational(options, stage);
    }
  }
  throw std::logic_error("solvers::run_method: unknown method");
}

}  // namespace cartan::solvers
