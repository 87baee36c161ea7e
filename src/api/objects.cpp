// api::verify and api::along for problems given as objects (erased.hpp): the kernels' compiled
// verifiers and quantities along a solution (kernels/lie_group/compiled.hpp, kernels/manifold/
// compiled.hpp) on samples in numbers, for every shipped group and manifold, with the decisions
// every door shares: the resolution and (on a manifold) the frame at q0 taken from the samples, and
// the verdict of a failed result without samples.
#include <algorithm>

#include "cartan/api/erased.hpp"
#include "cartan/errors.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/manifold/compiled.hpp"
#include "samples.hpp"

namespace cartan::api {

namespace {

int steps_of(const Samples& x) { return std::max<int>(1, static_cast<int>(x.t.size()) - 1); }

}  // namespace

template <groups::LieGroup G>
verify::Report verify(const GroupObjectProblem<G>& problem, const Samples& x, int order, double tol, Status status,
                      std::string_view where) {
  detail::check_samples(x, groups::ElementOf<G>::SizeAtCompileTime, G::kDim, G::kDim, where);
  if (x.t.size() == 0 && status != Status::Converged) return verify::unchecked_failure(status);
  GroupObjectProblem<G> posed = problem;
  posed.N = steps_of(x);
  return verify::verify_trajectory(posed, detail::lie_trajectory<G>(x), order, tol, status);
}

template <manifolds::ManifoldWithConnection M>
verify::Report verify(const ManifoldObjectProblem<M>& problem, const Samples& x, int order, double tol, Status status,
                      std::string_view where) {
  constexpr Eigen::Index n = M::kDim;
  detail::check_samples(x, manifolds::PointOf<M>::SizeAtCompileTime, n, n * n, where);
  detail::check_table(x, x.frames, "frames", manifolds::FrameOf<M>::SizeAtCompileTime, where, true);
  if (x.t.size() == 0 && status != Status::Converged) return verify::unchecked_failure(status);
  if (x.t.size() == 0) throw_invalid(where, "samples.t", "(empty)", "needs the samples of a solution");
  ManifoldObjectProblem<M> posed = problem;
  posed.N = steps_of(x);
  if (!posed.frame0 && x.frames.rows() > 0) posed.frame0 = detail::value_of_row<manifolds::FrameOf<M>>(x.frames, 0);
  return general::verify_general(posed, detail::general_trajectory<M>(x), order, tol, status);
}

template <groups::LieGroup G>
Along along(const mechanics::ErasedLagrangian<G>* lagrangian, double lambda, const Samples& x, std::string_view where) {
  detail::check_table(x, x.points, "points", groups::ElementOf<G>::SizeAtCompileTime, where);
  detail::check_table(x, x.v, "v", G::kDim, where);
  detail::check_table(x, x.mu, "mu", G::kDim, where, lagrangian == nullptr);
  detail::check_table(x, x.aux, "aux", G::kDim, where);
  const transported::TransportedTrajectory<G> tr = detail::lie_trajectory<G>(x);
  return detail::along_of<G>(lagrangian != nullptr ? transported::along_solution<G>(*lagrangian, lambda, tr)
                                                   : transported::along_transport<G>(lambda, tr));
}

template <manifolds::ManifoldWithConnection M>
Along along(const ManifoldObjectProblem<M>& problem, const Samples& x, std::string_view where) {
  constexpr Eigen::Index n = M::kDim;
  detail::check_table(x, x.points, "points", manifolds::PointOf<M>::SizeAtCompileTime, where);
  detail::check_table(x, x.frames, "frames", manifolds::FrameOf<M>::SizeAtCompileTime, where, true);
  detail::check_table(x, x.v, "v", n, where);
  detail::check_table(x, x.mu, "mu", n, where, true);
  detail::check_table(x, x.aux, "aux", n * n, where, true);
  return detail::along_of<M>(general::along_general(problem, detail::general_trajectory<M>(x)));
}

#define CARTAN_API_OBJECTS_ON_GROUP(G)                                                                                  \
  template verify::Report verify<G>(const GroupObjectProblem<G>&, const Samples&, int, double, Status, std::string_view); \
  template Along along<G>(const mechanics::ErasedLagrangian<G>*, double, const Samples&, std::string_view);
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_API_OBJECTS_ON_GROUP)
#undef CARTAN_API_OBJECTS_ON_GROUP
#define CARTAN_API_OBJECTS_ON_MANIFOLD(M)                                                                                  \
  template verify::Report verify<M>(const ManifoldObjectProblem<M>&, const Samples&, int, double, Status, std::string_view); \
  template Along along<M>(const ManifoldObjectProblem<M>&, const Samples&, std::string_view);
CARTAN_GENERAL_SHIPPED_MANIFOLDS(CARTAN_API_OBJECTS_ON_MANIFOLD)
#undef CARTAN_API_OBJECTS_ON_MANIFOLD

}  // namespace cartan::api
