#pragma once
// The api for problems given as objects rather than names (docs/design/one-door-bindings.md): a
// space object of the library (a group, a manifold, a chart with its callbacks) and samples in
// numbers (Samples, solve.hpp). What the Python module calls, so that it reaches the kernels only
// through the api. Compiled once in the library, cartan::cartan (src/api/dense.cpp), for the shipped groups and
// manifolds; a unit that includes this header sees the declarations only.

#include <string_view>
#include <vector>

#include "cartan/api/solve.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/manifolds/manifold.hpp"
#include "cartan/principle/vocabulary.hpp"

namespace cartan::api {

/// The dense output of samples of a solution by `method` (kernels/lie_group/dense.hpp: the
/// interpolation of each method, O(h^2) for the discrete schemes, O(h^3)-O(h^4) for collocation)
/// at `times`, on a group with the Lie-group kernel's samples (xi in aux) and its lambda: samples
/// whose t are `times`. Throws std::invalid_argument "<where>: ..." when a table has another
/// shape, x has fewer than 2 samples, or a time is outside [t_0, t_M] (NaN included).
template <groups::LieGroup G>
Samples dense(double lambda, const Samples& x, Method method, const std::vector<double>& times, std::string_view where);

/// The same on `space` with the general kernel's samples (their frames, Xi in aux)
/// (kernels/manifold/dense.hpp); it throws also when the piece of a step does not reach its end.
template <manifolds::ManifoldWithConnection M>
Samples dense(const M& space, const Samples& x, Method method, const std::vector<double>& times, std::string_view where);

}  // namespace cartan::api
