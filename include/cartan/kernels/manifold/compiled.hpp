#pragma once
// The general solver's entry points as declarations, and the list of what the library compiles of
// them: what a unit needs to call the library without parsing a solver. Compiled in the library
// (src/methods/solve_<manifold>.cpp, one file per manifold, in unity groups: CMakeLists.txt) for the erased Lagrangian
// (mechanics/manifold_erased_lagrangian.hpp; `erased(problem)` wraps any problem's) on every shipped manifold: the
// sphere, the hyperbolic plane, R^2 and R^3 with constant Christoffel symbols, charts of dimension
// 2 and 3, and SO(3), H3, SE(2), SE(3) with any left-invariant connection. Including this header
// costs a unit seconds; instantiating the solve costs it tens of seconds per manifold
// (bench/README.md, "Build time"). A call with any other (manifold, Lagrangian) pair through this
// header alone does not link: call it as `solve(erased(problem))`, or include the definitions
// (solve.hpp, shooting.hpp, verify.hpp) for the fully typed instantiation. The definition headers
// include this one, so the declarations (with the default arguments) are written once.

#include <optional>
#include <string>

#include "cartan/kernels/manifold/solution.hpp"
#include "cartan/manifolds/shipped.hpp"
#include "cartan/mechanics/check_report.hpp"
#include "cartan/mechanics/manifold_compiled.hpp"
#include "cartan/mechanics/manifold_erased_lagrangian.hpp"
#include "cartan/principle/manifold_problem.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/status.hpp"
#include "cartan/verify/verdict.hpp"

namespace cartan::general {

/// The problem of the compiled solve on M: any Lagrangian behind the erased type.
template <manifolds::ManifoldWithConnection M>
using ErasedProblem = GeneralProblem<M, ErasedLagrangian<M>>;

/// `problem` with its Lagrangian behind the erased type (for the compiled solvers).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
ErasedProblem<M> erased(const GeneralProblem<M, L>& problem) {
  return {problem.manifold, ErasedLagrangian<M>(problem.lagrangian), problem.T, problem.N, problem.q0, problem.qT,
          problem.frame0};
}

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
class GeneralScheme;
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
class GeneralSchemeTangent;

/// The N steps of the scheme from (v0, Xi0) (methods/manifold/shooting.hpp, where it is
/// documented): the last node, or nothing with `failure` set.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
std::optional<GeneralNode<M>> general_sweep(const GeneralScheme<M, L>& scheme, const manifolds::ComponentsOf<M>& v0,
                                            const manifolds::ComponentMatrixOf<M>& Xi0, std::string& failure,
                                            GeneralTrajectory<M>* trajectory = nullptr,
                                            const GeneralSchemeTangent<M, L>* tangent = nullptr,
                                            Eigen::MatrixXd* jacobian = nullptr, const SolveMonitor* monitor = nullptr,
                                            double after_stop = -1);

/// Solves the general problem as `options` say (solve.hpp). Throws std::invalid_argument for an
/// invalid problem or options, or a method this problem family does not have; numerical failure is
/// a status.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve(const GeneralProblem<M, L>& problem, const SolveOptions& options = {},
                         const GeneralGuess<M>& guess = {});

/// Single shooting of the general scheme from (v0_guess, Xi0_guess), or from the geodesic guess
/// (shooting.hpp).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve_general_shooting(const GeneralProblem<M, L>& problem, const GeneralShootingOptions& options,
                                          const manifolds::ComponentsOf<M>& v0_guess,
                                          const manifolds::ComponentMatrixOf<M>& Xi0_guess);
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve_general_shooting(const GeneralProblem<M, L>& problem, const GeneralShootingOptions& options = {});

/// Every check on `x` as a solution of `problem` to `tol` by a method of the given order
/// (verify.hpp); a `status` other than converged adds a failing `converged` check.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
verify::Report verify_general(const GeneralProblem<M, L>& problem, const GeneralTrajectory<M>& x, int order, double tol,
                              Status status = Status::Converged);

/// The frames, u = E v, energy and cumulative discrete action along `x` (along.hpp).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralAlong<M> along_general(const GeneralProblem<M, L>& problem, const GeneralTrajectory<M>& x);

}  // namespace cartan::general

/// `extern template` (declaration) or `template` (definition, in one src/methods/solve_*.cpp per manifold) of the solve, the
/// shooting it runs (both entry points), the verifier and the quantities along a solution for the
/// erased Lagrangian on M, and the mechanics compiled with them (mechanics/manifold_compiled.hpp).
#define CARTAN_GENERAL_COMPILED(prefix, M)                                                                     \
  prefix ::cartan::general::GeneralSolution<M> cartan::general::solve(                                        \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::SolveOptions&, const ::cartan::general::GeneralGuess<M>&);                  \
  prefix ::cartan::general::GeneralSolution<M> cartan::general::solve_general_shooting(                       \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::general::GeneralShootingOptions&, const ::cartan::manifolds::ComponentsOf<M>&,           \
      const ::cartan::manifolds::ComponentMatrixOf<M>&);                                                       \
  prefix ::cartan::general::GeneralSolution<M> cartan::general::solve_general_shooting(                       \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::general::GeneralShootingOptions&);                                                       \
  prefix ::cartan::verify::Report cartan::general::verify_general(                                              \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::general::GeneralTrajectory<M>&, int, double, ::cartan::Status);                    \
  prefix ::cartan::general::GeneralAlong<M> cartan::general::along_general(                                   \
      const ::cartan::general::GeneralProblem<M, ::cartan::general::ErasedLagrangian<M>>&,                     \
      const ::cartan::general::GeneralTrajectory<M>&);                                                         \
  prefix std::optional<::cartan::general::GeneralNode<M>> cartan::general::general_sweep(                       \
      const ::cartan::general::GeneralScheme<M, ::cartan::general::ErasedLagrangian<M>>&,                      \
      const ::cartan::manifolds::ComponentsOf<M>&, const ::cartan::manifolds::ComponentMatrixOf<M>&,           \
      std::string&, ::cartan::general::GeneralTrajectory<M>*,                                                  \
      const ::cartan::general::GeneralSchemeTangent<M, ::cartan::general::ErasedLagrangian<M>>*,               \
      Eigen::MatrixXd*, const ::cartan::SolveMonitor*, double);

#define CARTAN_GENERAL_EXTERN(M) CARTAN_GENERAL_COMPILED(extern template, M)
CARTAN_GENERAL_SHIPPED_MANIFOLDS(CARTAN_GENERAL_EXTERN)
#undef CARTAN_GENERAL_EXTERN
