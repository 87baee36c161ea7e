#pragma once
// One entry point for the general transported-velocity problem (problem.hpp), with the vocabulary
// of every solve (principle/: SolveOptions, Method, Continuation, Status):
//   * Method::Shooting: shooting from the guess (default: the geodesic guess), or with
//     Continuation::T by continuation in the horizon;
//   * Method::Collocation: collocation of the continuous system (collocation.hpp) from the guess
//     trajectory or the geodesic guess (solvers::collocate, every kernel's driver); with
//     Continuation::T, when Newton fails on the start's mesh, from the order-2 shooting solution
//     of the kernel below (shooting, then continuation in T);
//   * Method::Auto (default): the default strategy of every solve (solvers/strategy.hpp) with this
//     kernel's capabilities (StrategyKernel below): shooting from the guess, continuation in T,
//     on the Lie-group kernel continuation in lambda, collocation polished by shooting, on the
//     Lie-group kernel multiple shooting; the first success is returned and `branch` names the path.
// Continuation in T is every kernel's path (solvers/continuation.hpp, through
// ShootingFamily): halve the horizon (same step h, so N scales with T) until shooting from the
// geodesic guess converges, then lengthen it with a secant predictor, accepting a stage only near
// its prediction. A failure returns the best iterate of the requested problem (never a stage at
// another T), and `branch` names the path.
// Multiple shooting, two-level and continuation in lambda are the Lie-group kernel's capabilities:
// on a Lie group whose connection is Cartan–Schouten given by its lambda with frame0 the identity,
// continuation in lambda runs on the kernel's problem family (general's status rule on every
// stage, as continuation in T), the other two as transported::solve runs them (on the kernel's
// problem behind the erased reduced Lagrangian, whose solve the library compiles for SO(3), H3,
// SE(2) and SE(3): transported/compiled.hpp),
// with general's status rule and the result converted (their trajectories are the scheme's, so the
// frame and Xi rebuild exactly); anywhere else (another group included) asking for them is an error
// naming them. The variational method stays the Lie-group solve's: its node velocities are means
// of its steps' (variational.hpp), not a trajectory of the scheme, so no frame of the general
// scheme can be rebuilt from them.
// Kernels: shooting and continuation in T run on the general scheme (shooting.hpp), or, on a Lie
// group whose connection is Cartan–Schouten given by its lambda with frame0 the identity, on the
// Lie-group scheme, whose result is converted (lie_kernel.hpp; docs/design/lie-kernel.md): the same
// discrete equations with 2m unknowns instead of m + m^2, and the same strategy, branches and
// status rules. Collocation is always the general one. solve_general_shooting is the general
// kernel alone.

#include <chrono>
#include <optional>
#include <sstream>

#include "cartan/general/collocation.hpp"
#include "cartan/general/compiled.hpp"
#include "cartan/general/lie_kernel.hpp"
#include "cartan/general/shooting.hpp"
#include "cartan/mechanics/legendre_check.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/solvers/continuation.hpp"
#include "cartan/solvers/strategy.hpp"
#include "cartan/transported/compiled.hpp"

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
    Continuous(const GeneralProblem<M, L>& p, const GeneralTrajectory<M>* g, const Discrete& d)
        : system_of(p), guess(g), discrete(d) {}
    numerics::BvpSystem system() const override { return system_of.system(); }
    bool start(Eigen::VectorXd& t, Eigen::MatrixXd& y) const override {
      if (guess == nullptr) {
        system_of.geodesic_guess(t, y);
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
  const Continuous continuous(problem, guess.trajectory ? &*guess.trajectory : nullptr, discrete);
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
  const Problem& problem;

  const Problem& shooting_problem() const { return problem; }
  const manifolds::ComponentMatrixOf<M>& auxiliary(const manifolds::ComponentMatrixOf<M>& Xi0) const { return Xi0; }
  GeneralSolution<M> result(GeneralSolution<M>&& s) const { return std::move(s); }
};

/// The Lie-group kernel's guess (xi0 = C(Xi0), a trajectory's xi = C(Xi)): design §4.
template <groups::LieGroup G>
transported::SolveGuess<G> lie_guess(const GeneralGuess<manifolds::GroupManifold<G>>& guess) {
  transported::SolveGuess<G> lie;
  lie.v0 = guess.v0;
  if (guess.Xi0) lie.xi0 = aux_to_xi<G>(*guess.Xi0);
  if (guess.trajectory) {
    const GeneralTrajectory<manifolds::GroupManifold<G>>& x = *guess.trajectory;
    transported::TransportedTrajectory<G> path;
    path.t = x.t;
    path.g = x.q;
    path.v = x.v;
    path.mu = x.mu;
    for (const auto& Xi : x.Xi) path.xi.push_back(aux_to_xi<G>(Xi));
    lie.trajectory = std::move(path);
  }
  return lie;
}

/// A method of the Lie-group kernel (header comment): transported::solve of the kernel's problem
/// with its Lagrangian behind the erased type, then general's status rule.
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
transported::TransportedSolution<G> lie_solve(const LieKernelProblem<G, L>& kernel, const SolveOptions& options,
                                              const transported::SolveGuess<G>& guess) {
  transported::TransportedSolution<G> s = transported::solve(transported::erased(kernel), options, guess);
  apply_general_status_rule(kernel, s, options.tol);
  return s;
}

/// The general solve's kernels as the default strategy sees them (solvers/strategy.hpp):
/// shooting and continuation in T through `kernel` (GeneralKernel above, or LieKernel,
/// lie_kernel.hpp), its guess Xi0 entering as `kernel.auxiliary(Xi0)`; collocation the general
/// one (Newton per mesh capped at 40 iterations, so that a hopeless start ends early); on the
/// Lie-group kernel of a group the library compiles, also continuation in lambda (on the kernel's
/// family, like continuation in T), multiple shooting and the two-level scheme (lie_solve).
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
    if constexpr (kLieMethods) return kernel_.problem.lambda;
    return std::nullopt;
  }
  bool has_collocation() const override { return true; }
  bool has_multiple_shooting() const override { return kLieMethods; }
  /// The Lie-group kernel's is the Lie-group solve's (so that Auto takes the same path there). The
  /// general kernel's Levenberg–Marquardt often stalls 6 iterations before it descends: on the
  /// sphere (golden sphere_auto) a window of 6 sends it to continuation in T, 80 sweeps against
  /// 28 from the guess with 8.
  int first_shooting_window() const override { return kLieKernel ? ContinuationOptions{}.no_progress_window : 8; }

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
  /// The path in lambda on the Lie-group kernel's family (general's status rule on every stage,
  /// docs/design/one-core.md D10), from the solution at lambda = `start`.
  solvers::PathResultPtr continue_in_lambda(const ContinuationOptions& options, double start) override {
    if constexpr (kLieMethods) return wrap(solvers::detail::continue_in_lambda(kernel_.problem, start, options));
    throw std::logic_error("general::StrategyKernel: continuation in lambda is the Lie-group kernel's");
  }
  solvers::PathResultPtr collocate(const SolveOptions& options, int samples) override {
    SolveOptions c = options;
    c.max_iterations = std::min(options.max_iterations, 40);
    c.samples = samples;
    GeneralGuess<M> start;
    start.trajectory = guess_.trajectory;
    return solvers::wrap<Problem>(detail::collocation(problem_, c, start, *this));
  }
  /// transported::solve's (lie_solve), which reports to its own stage of `options`' monitor.
  solvers::PathResultPtr multiple_shoot(const SolveOptions& options, const SolveMonitor&) override {
    return lie_method(options, Method::MultipleShooting);
  }
  /// transported::solve's (lie_solve), which reports to its own stage of `options`' monitor.
  solvers::PathResultPtr two_level(const SolveOptions& options, const SolveMonitor&) override {
    return lie_method(options, Method::TwoLevel);
  }

  /// The strategy's result as the general solve's.
  GeneralSolution<M> take(solvers::PathResultPtr r) const {
    if (auto* of = dynamic_cast<solvers::detail::ResultOf<Family>*>(r.get())) return kernel_.result(std::move(of->value));
    return solvers::take<Problem>(std::move(r));
  }

 private:
  static constexpr bool kLieKernel = requires { typename Kernel::Group; };
  static constexpr bool kLieMethods = [] {
    if constexpr (kLieKernel) return transported::kCompiledGroup<typename Kernel::Group>;
    return false;
  }();

  template <class Solution>
  static solvers::PathResultPtr wrap(Solution s) {
    return solvers::wrap<KernelProblem>(std::move(s));
  }
  /// A method of the Lie-group kernel, as transported::solve runs it (lie_solve), from the guess.
  solvers::PathResultPtr lie_method(const SolveOptions& options, Method method) const {
    if constexpr (kLieMethods) {
      SolveOptions o = options;
      o.method = method;
      return wrap(lie_solve(kernel_.problem, o, lie_guess(guess_)));
    }
    throw std::logic_error("general::StrategyKernel: " + std::string(to_string(method)) + " is the Lie-group kernel's");
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
/// (GeneralKernel above or LieKernel, lie_kernel.hpp) as StrategyKernel above offers them:
/// every method's choice is the compiled solvers::run_method's (Auto the default strategy,
/// Shooting from the guess, a guess Xi0 entering as `auxiliary(Xi0)`, or continued in T or in
/// lambda); `take` makes the returned solution a GeneralSolution<M>.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L, class Kernel>
GeneralSolution<M> run_strategy(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                                const GeneralGuess<M>& guess, const Kernel& kernel) {
  StrategyKernel<M, L, Kernel> methods(problem, options, guess, kernel);
  return methods.take(solvers::run_method(methods, options));
}

/// run_strategy on the general scheme.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> run_methods(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                               const GeneralGuess<M>& guess) {
  return run_strategy(problem, options, guess, GeneralKernel<M, L>{problem});
}

/// run_strategy on the Lie-group scheme of the Cartan–Schouten connection of parameter `lambda`
/// (lie_kernel.hpp; where lie_kernel_applies).
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
GeneralSolution<manifolds::GroupManifold<G>> run_methods_lie(const GeneralProblem<manifolds::GroupManifold<G>, L>& problem,
                                                             double lambda, const SolveOptions& options,
                                                             const GeneralGuess<manifolds::GroupManifold<G>>& guess) {
  return run_strategy(problem, options, guess, LieKernel<G, L>{lie_kernel_problem(problem, lambda)});
}

}  // namespace detail

/// Solves the general problem. Throws std::invalid_argument for an invalid problem or options,
/// or a method this problem family does not have; numerical failure is a status. solve_time_s is
/// the whole call's, every attempt of the strategy included. Shooting runs on the Lie-group kernel
/// where lie_kernel_applies, and the kernel's own methods where it is available (header comment),
/// the message then starting "Lie-group kernel".
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                         const GeneralGuess<M>& guess) {
  problem.validate();
  options.validate();
  // The inverse Legendre map, at t = 0, q0 and t = T, qT, on the geodesic velocity (where qT is
  // not at q0's cut locus) and the basis vectors (D11 of docs/design/one-core.md).
  std::optional<manifolds::ComponentsOf<M>> geodesic;
  try {
    geodesic = geodesic_guess(problem);
  } catch (const std::exception&) {  // difference(q0, qT) undefined there: the solve will say so
  }
  if (geodesic && !geodesic->allFinite()) geodesic.reset();
  mechanics::check_legendre_inverse<L, manifolds::PointOf<M>, manifolds::ComponentsOf<M>>(
      "general::solve", problem.lagrangian, {{0.0, problem.q0}, {problem.T, problem.qT}}, geodesic);
  // The Lie-group kernel's own methods (header comment): multiple shooting, two-level, and
  // continuation in lambda of shooting.
  const bool collocation = options.method == Method::Collocation;
  const bool lie_method = options.method == Method::MultipleShooting || options.method == Method::TwoLevel ||
                          (options.continuation == Continuation::Lambda && !collocation);
  bool lie_kernel = false;
  if constexpr (kIsGroupManifold<M>) {
    lie_kernel = lie_kernel_available(problem) && transported::kCompiledGroup<typename M::Group>;
  }
  if (options.continuation == Continuation::Lambda && (collocation || !lie_kernel)) {
    throw_invalid("general::solve", "continuation", "lambda",
                  collocation ? "is not available with collocation, which is the general one (continuation: none, T)"
                              : "needs a Cartan–Schouten connection on SO(3), H3, SE(2) or SE(3), given by lambda, "
                                "with the identity frame0 (general connections: none, T)");
  }
  if (options.method == Method::Variational || (lie_method && !lie_kernel)) {
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
  const auto start = std::chrono::steady_clock::now();
  const SolveOptions timed = with_deadline(options, start);
  GeneralSolution<M> s = [&] {
    if constexpr (kIsGroupManifold<M>) {
      if (lie_kernel_applies(problem, timed)) {
        return detail::run_methods_lie(problem, *problem.manifold.cartan_schouten_lambda(), timed, guess);
      }
    }
    return detail::run_methods(problem, timed, guess);
  }();
  apply_time_limit(timed, s.status, s.message);
  s.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace cartan::general
