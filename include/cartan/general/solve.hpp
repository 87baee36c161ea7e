#pragma once
// One entry point for the general transported-velocity problem (problem.hpp), with the vocabulary
// of every solve (principle/: SolveOptions, Method, Continuation, Status):
//   * Method::Shooting: shooting from the guess (default: the geodesic guess), or with
//     Continuation::T by continuation in the horizon;
//   * Method::Collocation: collocation of the continuous system (collocation.hpp) from the guess
//     trajectory or the geodesic guess; with Continuation::T, when Newton from the geodesic guess
//     fails on the N-interval mesh, from the order-2 shooting solution found by continuation in T;
//   * Method::Auto (default): shooting from the guess, then continuation in T, then collocation
//     from the geodesic guess; the first success is returned and `branch` names the path.
// Continuation in T is every kernel's path (solvers/continuation.hpp, through
// ShootingFamily): halve the horizon (same step h, so N scales with T) until shooting from the
// geodesic guess converges, then lengthen it with a secant predictor, accepting a stage only near
// its prediction. A failure returns the best iterate of the requested problem (never a stage at
// another T), and `branch` names the path.
// Multiple shooting, two-level and continuation in lambda are the Lie-group kernel's capabilities:
// on a Lie group whose connection is Cartan–Schouten given by its lambda with frame0 the identity
// they run as transported::solve runs them (on the kernel's problem behind the erased reduced
// Lagrangian, whose solve the library compiles for SO(3), H3, SE(2) and SE(3): transported/compiled.hpp),
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
#include "cartan/principle/options.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/solvers/continuation.hpp"
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
  static int inner_iterations(const Solution&) { return 0; }  // one level: no inner iterations
  static void set_inner_iterations(Solution&, int) {}
};

}  // namespace cartan::solvers

namespace cartan::general {

namespace detail {

/// Continuation in T (solvers/continuation.hpp's path) of a problem family: the general
/// problem (ShootingFamily above) or the Lie kernel's (lie_kernel.hpp). `direct` is the failed
/// attempt at the full horizon, not repeated (pass it moved: the path keeps it).
template <class Problem, class Solution = typename solvers::ShootingFamily<Problem>::Solution>
Solution continue_in_T(const Problem& problem, const GeneralShootingOptions& shooting, Solution direct) {
  ContinuationOptions options;
  options.shooting = shooting;
  Solution result = solvers::detail::continue_in_T(problem, options, std::nullopt, std::nullopt, &direct);
  result.branch = "continuation in T (" + result.branch + ")";
  return result;
}

/// Method::Collocation (header comment).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> collocation(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                               const GeneralGuess<M>& guess) {
  const SolveMonitor stage = options.monitor.stage("collocation");
  const numerics::CollocationOptions c{.tol = options.tol,
                                       .max_nodes = options.max_nodes.value_or(kDefaultMaxNodes),
                                       .max_newton_iterations = options.max_iterations,
                                       .monitor = &stage};
  const GeneralTrajectory<M>* start = guess.trajectory ? &*guess.trajectory : nullptr;
  const bool fallback = !start && options.continuation == Continuation::T;
  GeneralSolution<M> s = solve_general_collocation(problem, c, options.samples, start, !fallback);
  if (!fallback || s.converged() || s.status == Status::Interrupted) return s;
  const double seconds = s.solve_time_s;
  GeneralShootingOptions shooting{.order = SchemeOrder::Second, .tolerance = options.tol,
                                  .max_iterations = options.max_iterations, .no_progress_window = 8,
                                  .monitor = &options.monitor};
  GeneralSolution<M> direct = solve_general_shooting(problem, shooting);
  direct.branch = "shooting from the geodesic guess";
  GeneralSolution<M> path = direct.converged() ? std::move(direct) : continue_in_T(problem, shooting, std::move(direct));
  if (!path.converged()) {
    s.status = Status::ContinuationFailed;
    s.message += "; the order-2 shooting fallback failed too: " + path.message;
    s.branch += " (Newton failed on the N-interval mesh)";
    s.solve_time_s += path.solve_time_s;
    return s;
  }
  GeneralSolution<M> refined = solve_general_collocation(problem, c, options.samples, &path.trajectory);
  refined.branch = "collocation from the order-2 shooting solution (" + path.branch +
                   ") after Newton from the geodesic guess failed on the N-interval mesh";
  refined.solve_time_s += seconds + path.solve_time_s;
  return refined;
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

/// The methods of solve (below) after its checks, under the options' deadline, with the shooting
/// and continuation in T of `kernel` (GeneralKernel above or LieKernel, lie_kernel.hpp): its
/// `shooting_problem()` is shot through its ShootingFamily, a guess Xi0 enters as
/// `auxiliary(Xi0)`, and `result` makes the returned solution a GeneralSolution<M>.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L, class Kernel>
GeneralSolution<M> run_strategy(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                                const GeneralGuess<M>& guess, const Kernel& kernel) {
  using Family = solvers::ShootingFamily<typename Kernel::Problem>;
  if (options.method == Method::Collocation) return detail::collocation(problem, options, guess);
  GeneralShootingOptions shooting{.order = options.order, .tolerance = options.tol,
                                  .max_iterations = options.max_iterations, .no_progress_window = 0,
                                  .monitor = &options.monitor};
  const bool auto_strategy = options.method == Method::Auto;
  if (auto_strategy) shooting.no_progress_window = 8;
  const std::string from =
      guess.v0 || guess.Xi0 || guess.trajectory ? "from the given guess" : "from the geodesic guess";
  const GeneralTrajectory<M>* path = guess.trajectory ? &*guess.trajectory : nullptr;
  auto direct = Family::shoot(
      kernel.shooting_problem(), shooting, path ? path->v.front() : guess.v0.value_or(geodesic_guess(problem)),
      kernel.auxiliary(path ? path->Xi.front() : guess.Xi0.value_or(manifolds::ComponentMatrixOf<M>::Zero())));
  direct.branch = "shooting (" + from + ")";
  if (direct.converged() || direct.status == Status::Interrupted ||
      (!auto_strategy && options.continuation == Continuation::None)) {
    return kernel.result(std::move(direct));
  }
  auto continued = detail::continue_in_T(kernel.shooting_problem(), shooting, std::move(direct));
  if (!auto_strategy || continued.converged() || continued.status == Status::Interrupted) {
    if (auto_strategy) continued.branch += ", after shooting failed";
    return kernel.result(std::move(continued));
  }
  SolveOptions c = options;
  c.method = Method::Collocation;
  c.max_iterations = std::min(options.max_iterations, 40);  // Newton per mesh: a hopeless start ends early
  GeneralGuess<M> start;
  start.trajectory = guess.trajectory;
  GeneralSolution<M> collocated = detail::collocation(problem, c, start);
  if (collocated.converged()) {
    collocated.branch += ", after shooting and continuation in T failed";
    return collocated;
  }
  GeneralSolution<M> failed = kernel.result(std::move(continued));
  failed.status = collocated.status == Status::Interrupted ? Status::Interrupted : Status::StrategyFailed;
  failed.message = "every method of the default strategy failed (shooting " + from +
                   ", continuation in T, collocation): " + failed.message + "; collocation: " + collocated.message;
  return failed;
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

/// The Lie-group kernel's own methods (header comment): transported::solve of the kernel's problem
/// with its Lagrangian behind the erased type, a guess as the Lie-group solver's (xi = C(Xi)),
/// general's status rule, the result converted (general_solution_from_lie).
template <groups::LieGroup G, ManifoldLagrangian<manifolds::GroupManifold<G>> L>
GeneralSolution<manifolds::GroupManifold<G>> run_lie_method(const GeneralProblem<manifolds::GroupManifold<G>, L>& problem,
                                                            double lambda, const SolveOptions& options,
                                                            const GeneralGuess<manifolds::GroupManifold<G>>& guess) {
  const LieKernelProblem<G, L> kernel = lie_kernel_problem(problem, lambda);
  transported::SolveGuess<G> lie_guess;
  lie_guess.v0 = guess.v0;
  if (guess.Xi0) lie_guess.xi0 = aux_to_xi<G>(*guess.Xi0);
  if (guess.trajectory) {
    const GeneralTrajectory<manifolds::GroupManifold<G>>& x = *guess.trajectory;
    transported::TransportedTrajectory<G> path;
    path.t = x.t;
    path.g = x.q;
    path.v = x.v;
    path.mu = x.mu;
    for (const auto& Xi : x.Xi) path.xi.push_back(aux_to_xi<G>(Xi));
    lie_guess.trajectory = std::move(path);
  }
  transported::TransportedSolution<G> s = transported::solve(transported::erased(kernel), options, lie_guess);
  apply_general_status_rule(kernel, s, options.tol);
  return general_solution_from_lie(kernel, std::move(s));
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
      if constexpr (transported::kCompiledGroup<typename M::Group>) {
        if (lie_method) {
          return detail::run_lie_method(problem, *problem.manifold.cartan_schouten_lambda(), timed, guess);
        }
      }
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
