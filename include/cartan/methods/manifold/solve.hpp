#pragma once
// The manifold kernel's methods for the general transported-velocity problem (principle/manifold_problem.hpp), with
// the vocabulary of every solve (principle/: SolveOptions, Method, Continuation, Status), run on a
// shooting kernel that the one solve (methods/solve.hpp, where the kernel is chosen) hands in:
//   * Method::Shooting: shooting from the guess (default: the geodesic guess), or with
//     Continuation::T by continuation in the horizon;
//   * Method::Collocation: collocation of the continuous system (collocation.hpp) from the guess
//     trajectory or the geodesic guess (solvers::collocate, every kernel's driver); with
//     Continuation::T, when Newton fails on the start's mesh, from the order-2 shooting solution
//     of the shooting kernel (shooting, then continuation in T);
//   * Method::Auto (default): the default strategy of every solve (solvers/strategy.hpp) with the
//     shooting kernel's capabilities (StrategyKernel below): shooting from the guess, continuation
//     in T, where the kernel has them continuation in lambda, collocation polished by shooting,
//     multiple shooting; the first success is returned and `branch` names the path.
// Continuation in T is every kernel's path (solvers/continuation.hpp, through
// ShootingFamily): halve the horizon (same step h, so N scales with T) until shooting from the
// geodesic guess converges, then lengthen it with a secant predictor, accepting a stage only near
// its prediction. A failure returns the best iterate of the requested problem (never a stage at
// another T), and `branch` names the path.
// The shooting kernel (the interface below, "ShootingKernel"): this kernel's own (GeneralKernel:
// the general scheme, shooting.hpp, unknowns (v0, Xi0)), or another kernel presented in this
// kernel's vocabulary (the Lie-group kernel on a Cartan–Schouten group:
// methods/lie_group_as_manifold.hpp), which may add multiple shooting, two-level and continuation in
// lambda (kHasGroupMethods). Collocation is always this kernel's. solve_general_shooting is the
// general scheme alone.
//
// A shooting kernel `K` offers:
//   K::Problem                      its shooting problem (a family of solvers::ShootingFamily),
//   shooting_problem()              that problem,
//   auxiliary(Xi0)                  a guess Xi0 as the family's auxiliary unknown,
//   result(solution)                the family's solution as a GeneralSolution<M>,
//   K::kHasGroupMethods             whether it has the methods below, and if so
//   lambda(), continue_in_lambda(options, start), run(options, method, guess)
//                                   (multiple shooting, two-level), first_shooting_window().

#include <chrono>
#include <optional>
#include <sstream>

#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/mechanics/legendre_check.hpp"
#include "cartan/methods/manifold/collocation.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/solvers/continuation.hpp"
#include "cartan/solvers/strategy.hpp"

namespace cartan::solvers {

/// The general problem as a family of the continuation path: unknowns (v0, Xi0).
template <manifolds::ManifoldWithConnection M, general::ManifoldLagrangian<M> L>
struct ShootingFamily<general::GeneralProblem<M, L>> {
  using Problem = general::GeneralProblem<M, L>;
  using Solution = general::GeneralSolution<M>;
  using Velocity = manifolds::ComponentsOf<M>;
  using Auxiliary = manifolds::ComponentMatrixOf<M>;
  static Solution shoot(const Problem& p, const ShootingOptions& o, const Velocity& v, const Auxiliary& a) {
    return general::solve_general_shooting(p, o, v, a);
  }
  static const Velocity& velocity(const Solution& s) { return s.v0; }
  static const Auxiliary& auxiliary(const Solution& s) { return s.Xi0; }
  static Velocity guess(const Problem& p) { return general::geodesic_guess(p); }
  static double auxiliary_scale(const Problem& p) { return general::xi_scale(p); }
  static constexpr bool kSumsInnerIterations = true;  // along a path (docs/design/one-core.md, D8)
};

}  // namespace cartan::solvers

namespace cartan::general {

namespace detail {

/// Method::Collocation (header comment), through the collocation driver of every kernel
/// (solvers::collocate): the general continuous system (collocation.hpp) from the guess
/// trajectory or the geodesic guess, Newton on the start's mesh first; with Continuation::T its
/// fallback runs on `discrete` (StrategyKernel below, of the same problem and guess), whose
/// `take` turns a shooting result into a GeneralSolution. Counters are summed over every run.
/// Reached from solve (below) only, whose checks cover the problem and the options' samples.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L, class Discrete>
GeneralSolution<M> collocation(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                               const GeneralGuess<M>& guess, Discrete& discrete) {
  const auto clock = std::chrono::steady_clock::now();
  const SolveMonitor stage = options.monitor.stage("collocation");
  const numerics::CollocationOptions c{.tol = options.tol,
                                       .max_nodes = options.max_nodes.value_or(kDefaultMaxNodes),
                                       .max_newton_iterations = options.max_iterations,
                                       .monitor = &stage};
  struct Continuous final : solvers::ContinuousProblem {
    const GeneralCollocation<M, L> system_of;
    const GeneralTrajectory<M>* guess;
    const Discrete& discrete;
    const SolveMonitor* monitor;
    Continuous(const GeneralProblem<M, L>& p, const GeneralTrajectory<M>* g, const Discrete& d, const SolveMonitor* m)
        : system_of(p), guess(g), discrete(d), monitor(m) {}
    numerics::BvpSystem system() const override { return system_of.system(); }
    bool start(Eigen::VectorXd& t, Eigen::MatrixXd& y) const override {
      if (guess == nullptr) {
        system_of.geodesic_guess(t, y, monitor);
        return false;
      }
      GeneralCollocation<M, L>::guess_from(*guess, t, y);
      return true;
    }
    void start_from(solvers::PathResultPtr shooting, Eigen::VectorXd& t, Eigen::MatrixXd& y) const override {
      GeneralCollocation<M, L>::guess_from(discrete.take(std::move(shooting)).trajectory, t, y);
    }
    // From a poor start the adaptive solver alone refines a diverged iterate up to max_nodes
    // (measured on SO(3) under a Levi-Civita connection).
    bool starts_on_mesh() const override { return true; }
  };
  const Continuous continuous(problem, guess.trajectory ? &*guess.trajectory : nullptr, discrete, &stage);
  const solvers::Collocated r = solvers::collocate(continuous, discrete, options.continuation, c);
  GeneralSolution<M> s =
      general_collocation_solution(continuous.system_of, r.result, solvers::output_times(r.result, options.samples, problem.T));
  s.branch = r.branch;
  s.sweeps += r.shooting_sweeps;
  s.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  return s;
}

/// run_strategy's shooting on the general scheme: the general problem's family (ShootingFamily
/// above), Xi0 as it is, results as they are.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
struct GeneralKernel {
  using Problem = GeneralProblem<M, L>;
  static constexpr bool kHasGroupMethods = false;
  const Problem& problem;

  const Problem& shooting_problem() const { return problem; }
  const manifolds::ComponentMatrixOf<M>& auxiliary(const manifolds::ComponentMatrixOf<M>& Xi0) const { return Xi0; }
  GeneralSolution<M> result(GeneralSolution<M>&& s) const { return std::move(s); }
};

/// The general solve's kernels as the default strategy sees them (solvers/strategy.hpp):
/// shooting and continuation in T through `kernel` (a shooting kernel: header comment), its guess
/// Xi0 entering as `kernel.auxiliary(Xi0)`; collocation the general one (Newton per mesh capped at
/// 40 iterations, so that a hopeless start ends early); where the kernel has them
/// (Kernel::kHasGroupMethods), also continuation in lambda, multiple shooting and the two-level
/// scheme, as the kernel runs them.
/// Results stay the kernel's own until `take` converts the strategy's.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L, class Kernel>
class StrategyKernel final : public solvers::StrategyKernel {
 public:
  using Problem = GeneralProblem<M, L>;
  using KernelProblem = typename Kernel::Problem;
  using Family = solvers::ShootingFamily<KernelProblem>;

  StrategyKernel(const Problem& problem, const SolveOptions& options, const GeneralGuess<M>& guess, const Kernel& kernel)
      : problem_(problem), options_(options), guess_(guess), kernel_(kernel) {}

  solvers::PathResultPtr empty() const override { return solvers::wrap<Problem>(GeneralSolution<M>{}); }
  double auxiliary_scale() const override { return Family::auxiliary_scale(kernel_.shooting_problem()); }
  bool guessed() const override { return !guess_.empty(); }
  int steps() const override { return problem_.N; }
  bool time_rescaling_invariant() const override { return false; }  // not known of a general Lagrangian
  std::optional<double> lambda() const override {
    if constexpr (Kernel::kHasGroupMethods) return kernel_.lambda();
    return std::nullopt;
  }
  bool has_collocation() const override { return true; }
  bool has_multiple_shooting() const override { return Kernel::kHasGroupMethods; }
  /// A kernel with the group methods says its own (the Lie-group solve's, so that Auto takes the
  /// same path there). The general kernel's Levenberg–Marquardt often stalls 6 iterations before it descends: on the
  /// sphere (golden sphere_auto) a window of 6 sends it to continuation in T, 80 sweeps against
  /// 28 from the guess with 8.
  int first_shooting_window() const override {
    if constexpr (requires(const Kernel& k) { k.first_shooting_window(); }) return kernel_.first_shooting_window();
    return 8;
  }

  solvers::PathResultPtr shoot(const ShootingOptions& options) override {
    return wrap(Family::shoot(kernel_.shooting_problem(), options, v0(), kernel_.auxiliary(Xi0())));
  }
  solvers::PathResultPtr shoot_from(const ShootingOptions& options, const solvers::PathResult& start) override {
    const GeneralSolution<M>& s = dynamic_cast<const solvers::detail::ResultOf<solvers::ShootingFamily<Problem>>&>(start).value;
    return wrap(Family::shoot(kernel_.shooting_problem(), options, s.v0, kernel_.auxiliary(s.Xi0)));
  }
  solvers::PathResultPtr continue_in_T(const ContinuationOptions& options, solvers::PathResultPtr failed_direct) override {
    std::optional<typename Family::Solution> direct;
    if (failed_direct != nullptr) direct = solvers::take<KernelProblem>(std::move(failed_direct));
    std::optional<typename Family::Velocity> v;
    std::optional<typename Family::Auxiliary> a;
    if (guessed()) {
      v = v0();
      a = kernel_.auxiliary(Xi0());
    }
    return wrap(solvers::detail::continue_in_T(kernel_.shooting_problem(), options, v, a, direct ? &*direct : nullptr));
  }
  /// The path in lambda, the kernel's (on the Lie-group kernel's family: general's status rule on every stage,
  /// docs/design/one-core.md D10), from the solution at lambda = `start`.
  solvers::PathResultPtr continue_in_lambda(const ContinuationOptions& options, double start) override {
    if constexpr (Kernel::kHasGroupMethods) return kernel_.continue_in_lambda(options, start);
    throw std::logic_error("general::StrategyKernel: continuation in lambda is not this kernel's");
  }
  solvers::PathResultPtr collocate(const SolveOptions& options, int samples) override {
    SolveOptions c = options;
    c.max_iterations = std::min(options.max_iterations, 40);
    c.samples = samples;
    GeneralGuess<M> start;
    start.trajectory = guess_.trajectory;
    return solvers::wrap<Problem>(detail::collocation(problem_, c, start, *this));
  }
  /// The kernel's, which reports to its own stage of `options`' monitor.
  solvers::PathResultPtr multiple_shoot(const SolveOptions& options, const SolveMonitor&) override {
    return group_method(options, Method::MultipleShooting);
  }
  /// The kernel's, which reports to its own stage of `options`' monitor.
  solvers::PathResultPtr two_level(const SolveOptions& options, const SolveMonitor&) override {
    return group_method(options, Method::TwoLevel);
  }

  /// The strategy's result as the general solve's.
  GeneralSolution<M> take(solvers::PathResultPtr r) const {
    if (auto* of = dynamic_cast<solvers::detail::ResultOf<Family>*>(r.get())) return kernel_.result(std::move(of->value));
    return solvers::take<Problem>(std::move(r));
  }

 private:
  template <class Solution>
  static solvers::PathResultPtr wrap(Solution s) {
    return solvers::wrap<KernelProblem>(std::move(s));
  }
  /// A method of the kernel (multiple shooting, two-level), as it runs it from the guess.
  solvers::PathResultPtr group_method(const SolveOptions& options, Method method) const {
    if constexpr (Kernel::kHasGroupMethods) {
      SolveOptions o = options;
      o.method = method;
      return kernel_.run(o, guess_);
    }
    throw std::logic_error("general::StrategyKernel: " + std::string(to_string(method)) + " is not this kernel's");
  }
  typename Family::Velocity v0() const { return guess_.start_v0().value_or(geodesic_guess(problem_)); }
  manifolds::ComponentMatrixOf<M> Xi0() const {
    return guess_.start_Xi0().value_or(manifolds::ComponentMatrixOf<M>::Zero());
  }

  const Problem& problem_;
  const SolveOptions& options_;
  const GeneralGuess<M>& guess_;
  const Kernel& kernel_;
};

/// The methods of solve (below) after its checks, under the options' deadline, on `kernel`
/// (GeneralKernel above, or another kernel in this kernel's vocabulary) as StrategyKernel offers them:
/// every method's choice is the compiled solvers::run_method's (Auto the default strategy,
/// Shooting from the guess, a guess Xi0 entering as `auxiliary(Xi0)`, or continued in T or in
/// lambda); `take` makes the returned solution a GeneralSolution<M>.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L, class Kernel>
GeneralSolution<M> run_strategy(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                                const GeneralGuess<M>& guess, const Kernel& kernel) {
  StrategyKernel<M, L, Kernel> methods(problem, options, guess, kernel);
  return methods.take(solvers::run_method(methods, options));
}

/// solve's checks of the request (methods/solve.hpp), after the problem's and the options' own:
/// the inverse Legendre map at t = 0, q0 and t = T, qT, on the geodesic velocity (where qT is not
/// at q0's cut locus) and the basis vectors (D11 of docs/design/one-core.md); the methods the
/// chosen kernels have (`group_methods`: multiple shooting, two-level and continuation in lambda,
/// the Lie-group kernel's on a Cartan–Schouten group the library compiles), each refused by name
/// elsewhere; the guess.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
void check_request(const GeneralProblem<M, L>& problem, const SolveOptions& options, const GeneralGuess<M>& guess,
                   bool group_methods) {
  std::optional<manifolds::ComponentsOf<M>> geodesic;
  try {
    geodesic = geodesic_guess(problem);
  } catch (const std::exception&) {  // difference(q0, qT) undefined there: the solve will say so
  }
  if (geodesic && !geodesic->allFinite()) geodesic.reset();
  mechanics::check_legendre_inverse<L, manifolds::PointOf<M>, manifolds::ComponentsOf<M>>(
      "general::solve", problem.lagrangian, {{0.0, problem.q0}, {problem.T, problem.qT}}, geodesic);
  const bool collocation = options.method == Method::Collocation;
  const bool group_method = options.method == Method::MultipleShooting || options.method == Method::TwoLevel ||
                            (options.continuation == Continuation::Lambda && !collocation);
  if (options.continuation == Continuation::Lambda && (collocation || !group_methods)) {
    throw_invalid("general::solve", "continuation", "lambda",
                  collocation ? "is not available with collocation, which is the general one (continuation: none, T)"
                              : "needs a Cartan–Schouten connection on SO(3), H3, SE(2) or SE(3), given by lambda, "
                                "with the identity frame0 (general connections: none, T)");
  }
  if (options.method == Method::Variational || (group_method && !group_methods)) {
    throw_invalid("general::solve", "method", std::string(to_string(options.method)),
                  "is not available for a general connection (methods: auto, shooting, collocation; on SO(3), "
                  "H3, SE(2), SE(3) with a Cartan–Schouten connection given by lambda and the identity frame0 also "
                  "multiple-shooting and two-level; variational: the Lie-group solve only, whose node "
                  "velocities are means of its steps' and carry no frame of the general scheme)");
  }
  if (guess.v0) require_finite(*guess.v0, "general::solve", "guess.v0");
  if (guess.Xi0) require_finite(*guess.Xi0, "general::solve", "guess.Xi0");
  if (guess.trajectory) {
    if (guess.v0 || guess.Xi0) throw std::invalid_argument("general::solve: give v0/Xi0 or a trajectory, not both");
    validate_trajectory(problem, *guess.trajectory, "general::solve", "guess.trajectory");
  }
}

/// The methods on `kernel` (run_strategy) under the options' deadline, from now (after the checks).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L, class Kernel>
GeneralSolution<M> solve_on(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                            const GeneralGuess<M>& guess, const Kernel& kernel) {
  const auto start = std::chrono::steady_clock::now();
  const SolveOptions timed = with_deadline(options, start);
  GeneralSolution<M> s = run_strategy(problem, timed, guess, kernel);
  apply_time_limit(timed, s.status, s.message, s.branch);
  s.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace detail

}  // namespace cartan::general
