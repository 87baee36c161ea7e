#pragma once
// One entry point for the transported-velocity problem (eq:reduced-system): solve(problem,
// options, guess) runs the requested method, or by default (Method::Auto) a strategy that tries
// cartan's methods in turn and stops at the first success (Method::Variational, the discrete
// Euler–Lagrange equations of S_h in variational.hpp, only when requested: its dense Newton
// costs O(N^3)). The CLI, the Python module and
// `cartan sweep` call this; the result it returns is complete (method used,
// branch, status, action), so no caller patches it.
//
// The choice of method is every kernel's (solvers/strategy.hpp, compiled once: run_method), and
// so is the default strategy: shooting, then continuation in T (unless the Lagrangian is purely
// kinetic), in lambda from 0 and from 1, collocation polished by shooting (natural Lagrangians),
// multiple shooting; this kernel says what it can do and runs each method (StrategyKernel below).

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "cartan/kernels/lie_group/action.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/lie_group/method.hpp"
#include "cartan/kernels/lie_group/solve_options.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/legendre_check.hpp"
#include "cartan/mechanics/natural_system.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/methods/lie_group/collocation_solution.hpp"
#include "cartan/methods/lie_group/continuation.hpp"
#include "cartan/methods/lie_group/multiple_shooting.hpp"
#include "cartan/methods/lie_group/two_level.hpp"
#include "cartan/methods/lie_group/variational.hpp"
#include "cartan/solvers/strategy.hpp"

namespace cartan::transported {

/// The potential V of a NaturalLagrangian<G, V> (void for any other Lagrangian): collocation
/// needs mu = I v with a constant inertia.
template <class L>
struct NaturalPotentialOf {
  using type = void;
};
template <groups::LieGroup G, mechanics::Potential<G> V>
struct NaturalPotentialOf<mechanics::NaturalLagrangian<G, V>> {
  using type = V;
};

/// Purely kinetic Lagrangians (no potential, no explicit time): the problem at horizon cT is the
/// problem at T with time rescaled, so continuation in T cannot help.
template <class L>
inline constexpr bool kPurelyKinetic = false;
template <groups::LieGroup G>
inline constexpr bool kPurelyKinetic<mechanics::NaturalLagrangian<G, mechanics::ZeroPotential<G>>> = true;

namespace detail {

/// A note when gT lies near the cut locus of g0 (e.g. a rotation by about pi): there log is
/// discontinuous, so the geodesic guess may point either way and the branch found depends on it.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
std::string cut_locus_note(const TransportedProblem<G, L>& problem) {
  const groups::ElementOf<G> d = G::compose(G::inverse(problem.g0), problem.gT);
  const groups::TangentOf<G> x = G::log(d);
  constexpr double eps = 1e-6;
  for (int i = 0; i < G::kDim; ++i) {
    const groups::TangentOf<G> y = G::log(G::compose(d, G::exp(groups::TangentOf<G>(eps * groups::TangentOf<G>::Unit(i)))));
    if ((y - x).norm() > 100 * eps * (1 + x.norm())) {
      return "gT is near the cut locus of g0 (log(g0^-1 gT) jumps under a perturbation of 1e-6): "
             "the geodesic guess's direction is ambiguous and the branch found depends on it";
    }
  }
  return {};
}

/// The check of the Lagrangian's inverse Legendre map (mechanics/legendre_check.hpp) at t = 0,
/// g0 and t = T, gT, on the geodesic velocity and the basis vectors.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void check_legendre_inverse(const TransportedProblem<G, L>& problem) {
  mechanics::check_legendre_inverse<L, groups::ElementOf<G>, groups::TangentOf<G>>(
      "solve", problem.lagrangian, {{0.0, problem.g0}, {problem.T, problem.gT}}, geodesic_guess(problem));
}

/// Fills what every result carries: the action S_h of its trajectory, the total time. A result
/// stopped on request keeps action NaN: over a long trajectory the action costs about two sweeps,
/// the work the stop (a time limit, Ctrl-C) was there to save.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void complete(const TransportedProblem<G, L>& problem, TransportedSolution<G>& s,
              std::chrono::steady_clock::time_point start) {
  const auto& tr = s.trajectory;
  if (stopped_on_request(s.status)) {
    s.action = std::numeric_limits<double>::quiet_NaN();
  } else if (tr.t.size() >= 2) {
    try {
      s.action = transported_action<G>(problem.lagrangian, problem.lambda, tr.t, tr.g);
    } catch (const std::invalid_argument&) {
      s.action = std::numeric_limits<double>::quiet_NaN();  // a user Lagrangian failed on this path
    }
  }
  s.solve_time_s = seconds_since(start);
}

/// Collocation needs mu = I v with a constant inertia (a NaturalLagrangian).
template <class L>
inline constexpr bool kNatural = !std::is_void_v<typename NaturalPotentialOf<L>::type>;

/// The input errors that depend on the method: the guesses and continuations it takes, and
/// collocation's need for a natural Lagrangian.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void check_method_inputs(const SolveOptions& options, const SolveGuess<G>& guess) {
  switch (options.method) {
    case Method::Shooting:
      if (options.continuation == Continuation::Lambda && !guess.empty()) {
        throw std::invalid_argument(
            "solve: continuation lambda starts from the solution at lambda_start and takes no guess (v0, xi0 "
            "or trajectory); use continuation none or T with a guess");
      }
      break;
    case Method::TwoLevel:
      if (guess.xi0) throw std::invalid_argument("solve: method two-level takes a v0 guess, not xi0 (xi starts at 0)");
      break;
    case Method::Collocation:
      if (guess.v0 || guess.xi0) throw std::invalid_argument("solve: method collocation takes a trajectory guess, not v0/xi0");
      if constexpr (!kNatural<L>) {
        throw_invalid("solve", "method", "collocation",
                      "needs a natural Lagrangian (mu = I v with a constant inertia), such as the built-in "
                      "models; the Legendre map of this one may depend on g");
      }
      if (std::is_same_v<G, groups::Heisenberg> && (guess.trajectory || options.continuation != Continuation::None)) {
        throw std::invalid_argument(
            "solve: method collocation on heisenberg takes no trajectory guess and no continuation (the "
            "closed-form collocation of H3 starts from the straight line in (a, b, c))");
      }
      break;
    case Method::Variational:
      if (guess.v0 || guess.xi0) {
        throw std::invalid_argument("solve: method variational takes a trajectory guess (its g), not v0/xi0");
      }
      break;
    case Method::Auto:
    case Method::MultipleShooting: break;
  }
}

/// The continuous problem by collocation (a natural Lagrangian; on H3 from the straight line, so
/// a trajectory guess and the continuation are not used there), its fallback on `discrete` (the
/// kernel below, of the same problem and guess).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
  requires kNatural<L>
TransportedSolution<G> collocation(const TransportedProblem<G, L>& problem, const SolveOptions& options,
                                   const SolveGuess<G>& guess, int samples, solvers::StrategyKernel& discrete) {
  const SolveMonitor stage = options.monitor.stage("collocation");
  const numerics::CollocationOptions c{.tol = options.tol,
                                       .max_nodes = options.max_nodes.value_or(kDefaultMaxNodes),
                                       .max_newton_iterations = options.max_iterations,
                                       .monitor = &stage};
  if constexpr (std::is_same_v<G, groups::Heisenberg>) {
    return solve_heisenberg_transported(problem, c, samples);
  } else {
    return solve_transported_by_collocation(problem, c, samples, options.continuation,
                                            guess.trajectory ? &*guess.trajectory : nullptr, discrete);
  }
}

/// The Lie-group kernel as the default strategy sees it (solvers/strategy.hpp): its methods on
/// `problem` from `guess`, its results PathResults of the problem's family.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class StrategyKernel final : public solvers::StrategyKernel {
 public:
  using Problem = TransportedProblem<G, L>;
  StrategyKernel(const Problem& problem, const SolveGuess<G>& guess) : problem_(problem), guess_(guess) {}

  solvers::PathResultPtr empty() const override { return wrap(TransportedSolution<G>{}); }
  double auxiliary_scale() const override { return xi_scale(problem_); }
  bool guessed() const override { return !guess_.empty(); }
  int steps() const override { return problem_.N; }
  bool time_rescaling_invariant() const override { return kPurelyKinetic<L>; }
  std::optional<double> lambda() const override { return problem_.lambda; }
  bool has_collocation() const override { return kNatural<L>; }
  bool has_multiple_shooting() const override { return true; }
  int first_shooting_window() const override { return ContinuationOptions{}.no_progress_window; }  // the path's

  solvers::PathResultPtr shoot(const ShootingOptions& options) override {
    return wrap(solve_shooting(problem_, options, v0(), xi0()));
  }
  solvers::PathResultPtr shoot_from(const ShootingOptions& options, const solvers::PathResult& start) override {
    const TransportedSolution<G>& s = dynamic_cast<const solvers::detail::ResultOf<Family>&>(start).value;
    return wrap(solve_shooting(problem_, options, s.v0, s.xi0));
  }
  solvers::PathResultPtr continue_in_T(const ContinuationOptions& options, solvers::PathResultPtr failed_direct) override {
    if (failed_direct == nullptr) {
      return wrap(solve_continuation_in_T(problem_, options, guess_.start_v0(), guess_.start_xi0()));
    }
    return wrap(solve_continuation_in_T(problem_, options, guess_.start_v0(), guess_.start_xi0(),
                                        solvers::take<Problem>(std::move(failed_direct))));
  }
  solvers::PathResultPtr continue_in_lambda(const ContinuationOptions& options, double start) override {
    return wrap(solve_continuation_in_lambda(problem_, start, options));
  }
  solvers::PathResultPtr collocate(const SolveOptions& options, int samples) override {
    if constexpr (kNatural<L>) return wrap(collocation(problem_, options, guess_, samples, *this));
    throw std::logic_error("transported::StrategyKernel: collocation needs a natural Lagrangian");
  }
  solvers::PathResultPtr multiple_shoot(const SolveOptions& options, const SolveMonitor& stage) override {
    const MultipleShootingOptions m{.order = options.order, .segments = options.segments, .tolerance = options.tol,
                                    .max_iterations = options.max_iterations, .monitor = &stage};
    return wrap(solve_multiple_shooting(problem_, m, v0(), xi0()));
  }
  solvers::PathResultPtr two_level(const SolveOptions& options, const SolveMonitor& stage) override {
    const TwoLevelOptions o{.order = options.order, .tolerance = options.tol, .max_outer = options.max_iterations,
                            .max_inner = options.max_iterations, .monitor = &stage};
    return wrap(solve_two_level(problem_, o, v0()));
  }
  solvers::PathResultPtr variational(const SolveOptions& options, const SolveMonitor& stage) override {
    const std::vector<groups::ElementOf<G>> path =
        guess_.trajectory ? path_at_nodes(problem_, *guess_.trajectory) : geodesic_path(problem_);
    TransportedSolution<G> s =
        solve_variational(problem_, {.tolerance = options.tol, .max_iterations = options.max_iterations, .monitor = &stage},
                          &path);
    s.branch = guess_.empty() ? "direct from the geodesic path" : "direct from the given trajectory";
    return wrap(std::move(s));
  }

 private:
  using Family = solvers::ShootingFamily<Problem>;
  static solvers::PathResultPtr wrap(TransportedSolution<G> s) { return solvers::wrap<Problem>(std::move(s)); }
  groups::TangentOf<G> v0() const { return guess_.start_v0().value_or(geodesic_guess(problem_)); }
  groups::CovectorOf<G> xi0() const { return guess_.start_xi0().value_or(groups::CovectorOf<G>::Zero()); }

  const Problem& problem_;
  const SolveGuess<G>& guess_;
};

}  // namespace detail

/// Throws std::invalid_argument for every problem, options and guess that solve() rejects, and
/// does no other work (a sweep checks all its problems before it solves any).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void validate(const TransportedProblem<G, L>& problem, const SolveOptions& options, const SolveGuess<G>& guess) {
  problem.validate();
  options.validate();
  guess.validate(problem.T);
  detail::check_legendre_inverse(problem);
  detail::check_method_inputs<G, L>(options, guess);
}

/// Solves `problem` as `options` say (header comment). Throws std::invalid_argument for a bad
/// problem, options or guess (validate), before any work; numerical failures are statuses.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve(const TransportedProblem<G, L>& problem, const SolveOptions& requested,
                             const SolveGuess<G>& guess) {
  validate(problem, requested, guess);
  const auto start = std::chrono::steady_clock::now();
  const SolveOptions options = with_deadline(requested, start);
  detail::StrategyKernel<G, L> kernel(problem, guess);
  TransportedSolution<G> s = solvers::take<TransportedProblem<G, L>>(solvers::run_method(kernel, options));
  if (const std::string note = detail::cut_locus_note(problem); !note.empty()) s.message += "; note: " + note;
  apply_time_limit(options, s.status, s.message, s.branch);
  detail::complete(problem, s, start);
  return s;
}

}  // namespace cartan::transported

// The built-in models' solve and validate are compiled once, in the library (compiled.hpp), not
// again in every unit that calls them: each instance is the heaviest code in cartan.
#define CARTAN_TRANSPORTED_EXTERN_MODEL(G, L) CARTAN_TRANSPORTED_COMPILED_MODEL(extern template, G, L)
CARTAN_TRANSPORTED_BUILTIN_MODELS(CARTAN_TRANSPORTED_EXTERN_MODEL)
#undef CARTAN_TRANSPORTED_EXTERN_MODEL
