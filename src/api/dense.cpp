// api::dense (erased.hpp): the kernels' compiled dense output (kernels/lie_group/dense.hpp,
// kernels/manifold/dense.hpp) on samples in numbers, for every shipped group and manifold; in the
// library target (cartan::cartan), which the Python module links.
#include "cartan/api/erased.hpp"

#include "cartan/kernels/lie_group/dense.hpp"
#include "cartan/kernels/manifold/dense.hpp"
#include "samples.hpp"

namespace cartan::api {

template <groups::LieGroup G>
Samples dense(double lambda, const Samples& x, Method method, const std::vector<double>& times, std::string_view where) {
  detail::check_samples(x, groups::ElementOf<G>::SizeAtCompileTime, G::kDim, G::kDim, where);
  return detail::samples_of(transported::dense_output<G>(detail::lie_trajectory<G>(x), lambda, method, times, where));
}

template <manifolds::ManifoldWithConnection M>
Samples dense(const M& space, const Samples& x, Method method, const std::vector<double>& times, std::string_view where) {
  detail::check_samples(x, manifolds::PointOf<M>::SizeAtCompileTime, M::kDim, M::kDim * M::kDim, where,
                        manifolds::FrameOf<M>::SizeAtCompileTime);
  return detail::samples_of(general::dense_output(space, detail::general_trajectory<M>(x), method, times, where));
}

#define CARTAN_API_DENSE_ON_GROUP(G) \
  template Samples dense<G>(double, const Samples&, Method, const std::vector<double>&, std::string_view);
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_API_DENSE_ON_GROUP)
#undef CARTAN_API_DENSE_ON_GROUP
#define CARTAN_API_DENSE_ON_MANIFOLD(M) \
  template Samples dense<M>(const M&, const Samples&, Method, const std::vector<double>&, std::string_view);
CARTAN_GENERAL_SHIPPED_MANIFOLDS(CARTAN_API_DENSE_ON_MANIFOLD)
#undef CARTAN_API_DENSE_ON_MANIFOLD

}  // namespace cartan::api
