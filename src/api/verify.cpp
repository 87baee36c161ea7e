// api::verify of a problem by names and numbers (solve.hpp): the problem as objects, then the
// objects' door (erased.hpp, objects.cpp), for the problem's kernel.
#include "cartan/api/erased.hpp"
#include "problems.hpp"

#include "cartan/errors.hpp"

namespace cartan::api {

namespace {

/// The numbers as the element they write, not projected (the checks see the data).
template <groups::LieGroup G>
groups::ElementOf<G> element(const std::vector<double>& numbers) {
  return value_of_numbers<groups::ElementOf<G>>(numbers);
}

/// The problem with its own frame at q0 (frame0, or the default), which the samples' first frame
/// (where a result in memory carries frames) does not replace: a problem by names is what it says.
template <class Problem>
Problem with_its_frame(Problem problem) {
  problem.frame0 = problem.initial_frame();
  return problem;
}

}  // namespace

verify::Report verify(const GroupProblem& problem, const Samples& samples, int order, double tol, Status status,
                      std::string_view where) {
  const detail::CheckedGroupProblem checked = detail::checked(problem, {}, true, where);
  const Eigen::Index n = checked.model->dim;
  detail::check_samples(samples, static_cast<Eigen::Index>(checked.model->element_size), n, lie_kernel(problem) ? n : n * n, where);
  return models::visit_model(problem.group, problem.model, where, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    const groups::ElementOf<G> g0 = element<G>(checked.g0), gT = element<G>(problem.gT);
    if (lie_kernel(problem)) {
      // Behind the erased Lagrangian, whose verify the library compiles: the model's own members
      // evaluated, so the figures of the typed verify (tests/kernels/lie_group/test_erased.cpp).
      const GroupObjectProblem<G> erased{mechanics::ErasedLagrangian<G>(models::make_lagrangian<Entry>(checked.inertia, where)),
                                         problem.lambda, problem.T, problem.N, g0, gT};
      return api::verify<G>(erased, samples, order, tol, status, where);
    }
    return api::verify<manifolds::GroupManifold<G>>(with_its_frame(detail::connection_problem<Entry>(problem, checked, g0, gT, where)),
                                                    samples, order, tol, status, where);
  });
}

verify::Report verify(const ManifoldProblem& problem, const Samples& samples, int order, double tol, Status status,
                      std::string_view where) {
  return detail::visit_manifold(problem, {}, where, [&]<class M>(const general::ErasedProblem<M>& posed) {
    return api::verify<M>(with_its_frame(posed), samples, order, tol, status, where);
  });
}

}  // namespace cartan::api
