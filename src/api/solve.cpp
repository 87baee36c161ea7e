// api::solve: the catalogue's model on its group through the kernel the connection allows, or the
// particle on a space of the catalogue (spaces.hpp) (solve.hpp); every solve is the library's compiled one (kernels/lie_group/ and
// kernels/manifold/compiled.hpp), so this unit instantiates only the conversions to numbers.
#include <limits>

#include "problems.hpp"

namespace cartan::api {

namespace {

/// A kernel's solution in numbers: its ResultCore moved, the samples (points, v, mu and the
/// auxiliary: xi where the Lie-group kernel ran, Xi row-major where the general one did) as rows.
template <class Solution>
Result result_of(Solution&& s, Samples&& samples, bool lie_kernel) {
  Result r;
  static_cast<ResultCore&>(r) = std::move(static_cast<ResultCore&>(s));
  r.lie_kernel = lie_kernel;
  r.samples = std::move(samples);
  return r;
}

template <groups::LieGroup G>
Result result_of(transported::TransportedSolution<G>&& s) {
  return result_of(std::move(s), detail::samples_of(s.trajectory), true);
}

/// A general solve's result with the discrete action along its samples (kernels/manifold/along.hpp),
/// as Python's result carries it: NaN for a result stopped on request or of fewer than two samples.
template <manifolds::ManifoldWithConnection M>
Result result_of(const general::ErasedProblem<M>& posed, general::GeneralSolution<M>&& s) {
  const bool along = !stopped_on_request(s.status) && s.trajectory.t.size() >= 2;
  const double action = along ? general::along_general(posed, s.trajectory).action.back()
                              : std::numeric_limits<double>::quiet_NaN();
  Result r = result_of(std::move(s), detail::samples_of(s.trajectory), false);
  r.action = action;
  return r;
}

template <class Vector>
Vector vector_of(const std::vector<double>& x) {
  return Eigen::Map<const Vector>(x.data());
}

}  // namespace

Result solve(const GroupProblem& problem, const cartan::SolveOptions& options, const Guess& guess, std::string_view where) {
  const detail::CheckedGroupProblem checked = detail::checked(problem, guess, true, where);
  return models::visit_model(problem.group, problem.model, where, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    const groups::ElementOf<G> g0 = models::element_of<G>(checked.g0), gT = models::element_of<G>(problem.gT);
    if (lie_kernel(problem)) {  // the model's own compiled solve (CARTAN_TRANSPORTED_BUILTIN_MODELS)
      const transported::TransportedProblem<G, typename Entry::Lagrangian> typed{
          models::make_lagrangian<Entry>(checked.inertia, where), problem.lambda, problem.T, problem.N, g0, gT};
      transported::SolveGuess<G> start;
      if (!guess.v0.empty()) start.v0 = vector_of<groups::TangentOf<G>>(guess.v0);
      if (!guess.xi0.empty()) start.xi0 = vector_of<groups::CovectorOf<G>>(guess.xi0);
      return result_of<G>(transported::solve(typed, options, start));
    }
    using M = manifolds::GroupManifold<G>;
    general::GeneralGuess<M> start;
    if (!guess.v0.empty()) start.v0 = vector_of<groups::TangentOf<G>>(guess.v0);
    const general::ErasedProblem<M> posed = detail::connection_problem<Entry>(problem, checked, g0, gT, where);
    return result_of<M>(posed, general::solve(posed, options, start));
  });
}

Result solve(const ManifoldProblem& problem, const cartan::SolveOptions& options, const Guess& guess, std::string_view where) {
  return detail::visit_manifold(problem, guess, where, [&]<class M>(const general::ErasedProblem<M>& posed) {
    general::GeneralGuess<M> start;
    if (!guess.v0.empty()) start.v0 = vector_of<manifolds::ComponentsOf<M>>(guess.v0);
    Result r = result_of<M>(posed, general::solve(posed, options, start));
    r.frame0 = posed.initial_frame().transpose();  // the rows e_1 .. e_m
    return r;
  });
}

}  // namespace cartan::api
