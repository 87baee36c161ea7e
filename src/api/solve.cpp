// api::solve of a problem by names and numbers (solve.hpp): the catalogue's model on its group, or the
// particle on a space of the catalogue (spaces.hpp), posed as objects and solved through the
// objects' door (erased.hpp, objects.cpp): the model's own compiled solve where the connection
// allows the Lie-group kernel, the general solve otherwise.
#include "cartan/api/erased.hpp"
#include "problems.hpp"

namespace cartan::api {

Result solve(const GroupProblem& problem, const cartan::SolveOptions& options, const Guess& guess, std::string_view where) {
  const detail::CheckedGroupProblem checked = detail::checked(problem, guess, true, where);
  return models::visit_model(problem.group, problem.model, where, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    const groups::ElementOf<G> g0 = models::element_of<G>(checked.g0), gT = models::element_of<G>(problem.gT);
    if (lie_kernel(problem)) {  // the model's own compiled solve (CARTAN_TRANSPORTED_BUILTIN_MODELS)
      const transported::TransportedProblem<G, typename Entry::Lagrangian> typed{
          models::make_lagrangian<Entry>(checked.inertia, where), problem.lambda, problem.T, problem.N, g0, gT};
      return api::solve(typed, options, guess, {}, where);
    }
    return api::solve(detail::connection_problem<Entry>(problem, checked, g0, gT, where), options, guess, {}, where);
  });
}

Result solve(const ManifoldProblem& problem, const cartan::SolveOptions& options, const Guess& guess, std::string_view where) {
  return detail::visit_manifold(problem, guess, where, [&]<class M>(const general::ErasedProblem<M>& posed) {
    Result r = api::solve(posed, options, guess, {}, where);
    r.frame0 = posed.initial_frame().transpose();  // the rows e_1 .. e_m
    return r;
  });
}

}  // namespace cartan::api
