#pragma once
// general::solve: the one place a kernel is chosen for the general transported-velocity problem
// (principle/manifold_problem.hpp), from what the space and its connection can do
// (docs/architecture.md, "Kernels"):
//   * on a Lie group whose connection is Cartan–Schouten given by its lambda, with frame0 unset or
//     the identity (lie_kernel_applies), shooting, continuation in T and in lambda, multiple
//     shooting and two-level run on the Lie-group kernel (kernels/lie_group/), presented in the
//     manifold kernel's vocabulary (methods/lie_group_as_manifold.hpp): the same discrete equations
//     with 2m unknowns instead of m + m^2, the result converted, the message starting "Lie-group
//     kernel";
//   * everywhere else, and collocation always, the manifold kernel (kernels/manifold/).
// Both are run by the manifold kernel's methods (methods/manifold/solve.hpp: the strategy, the
// paths and collocation, with the chosen kernel's shooting); what neither kernel has is refused
// by name. A group model (principle/group_problem.hpp) is a problem of the Lie-group kernel alone
// (transported::solve), whose methods include the variational one.

#include <optional>

#include "cartan/methods/lie_group_as_manifold.hpp"
#include "cartan/methods/manifold/solve.hpp"

namespace cartan::general {

/// Solves the general problem. Throws std::invalid_argument for an invalid problem or options,
/// or a method this problem family does not have; numerical failure is a status. solve_time_s is
/// the whole call's, every attempt of the strategy included. Declared with its default arguments
/// in kernels/manifold/compiled.hpp.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve(const GeneralProblem<M, L>& problem, const SolveOptions& options,
                         const GeneralGuess<M>& guess) {
  problem.validate();
  options.validate();
  bool group_methods = false;  // multiple shooting, two-level, continuation in lambda
  if constexpr (kIsGroupManifold<M>) {
    group_methods = lie_kernel_available(problem) && detail::LieKernel<typename M::Group, L>::kHasGroupMethods;
  }
  detail::check_request(problem, options, guess, group_methods);
  if constexpr (kIsGroupManifold<M>) {
    if (lie_kernel_applies(problem, options)) {
      using G = typename M::Group;
      const double lambda = *problem.manifold.cartan_schouten_lambda();
      return detail::solve_on(problem, options, guess, detail::LieKernel<G, L>{lie_kernel_problem(problem, lambda)});
    }
  }
  return detail::solve_on(problem, options, guess, detail::GeneralKernel<M, L>{problem});
}

}  // namespace cartan::general
