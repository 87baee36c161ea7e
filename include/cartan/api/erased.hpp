#pragma once
// The api for problems given as objects rather than names (docs/design/one-door-bindings.md): a
// space object of the library (a group, a manifold, a chart with its callbacks) and samples in
// numbers (Samples, solve.hpp). What the Python module calls, so that it reaches the kernels only
// through the api. Compiled once in the library, cartan::cartan (src/api/dense.cpp, objects.cpp),
// for the shipped groups and manifolds; a unit that includes this header sees the declarations only.

#include <string_view>
#include <vector>

#include "cartan/api/solve.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/manifolds/manifold.hpp"
#include "cartan/mechanics/erased_lagrangian.hpp"
#include "cartan/mechanics/manifold_erased_lagrangian.hpp"
#include "cartan/principle/group_problem.hpp"
#include "cartan/principle/manifold_problem.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/status.hpp"

namespace cartan::api {

/// A problem given as objects: any Lagrangian behind the erased type (a built-in model, a C++
/// user's, one written in Python) on a group with the Cartan–Schouten connection of lambda, whose
/// kernel is the Lie-group one ...
template <groups::LieGroup G>
using GroupObjectProblem = transported::TransportedProblem<G, mechanics::ErasedLagrangian<G>>;
/// ... or on a space object of the library with its connection (the general kernel).
template <manifolds::ManifoldWithConnection M>
using ManifoldObjectProblem = general::GeneralProblem<M, general::ErasedLagrangian<M>>;

/// What a solve computes besides its samples, where asked: `along` (Result::along).
struct SolveOutputs {
  bool along = false;
};

/// The library's compiled solve of `problem` (kernels/lie_group/compiled.hpp): L a built-in model
/// (CARTAN_TRANSPORTED_BUILTIN_MODELS) or the erased Lagrangian; the guess's v0 and xi0 (n numbers
/// each) or trajectory (the Lie-group kernel's samples; mu may have no rows). Returns the Result
/// with v0 and xi0 (aux0); along, with `outputs.along`, unless the solve was stopped on request.
/// Throws std::invalid_argument "<where>: ..." for a guess of another size or shape (Xi0 is the
/// general kernel's), and what the solve throws for the problem and options.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
Result solve(const transported::TransportedProblem<G, L>& problem, const SolveOptions& options, const Guess& guess,
             SolveOutputs outputs, std::string_view where);
/// Throws what solve would for the problem, the options and the guess, without solving.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void validate(const transported::TransportedProblem<G, L>& problem, const SolveOptions& options, const Guess& guess,
              std::string_view where);

/// The library's compiled general solve of `problem` (kernels/manifold/compiled.hpp: methods/solve.hpp
/// chooses the kernel; a Cartan–Schouten GroupManifold runs the Lie-group one), with the guess's v0
/// (m numbers), Xi0 (m^2, row-major) or trajectory (the general kernel's samples, with frames).
/// Returns the Result with v0 and Xi0 (aux0) and the action along the samples (NaN for a result
/// stopped on request or of fewer than two samples, which have no along); along with
/// `outputs.along`. Throws as the group's solve (xi0 is the Lie-group kernel's).
template <manifolds::ManifoldWithConnection M>
Result solve(const ManifoldObjectProblem<M>& problem, const SolveOptions& options, const Guess& guess, SolveOutputs outputs,
             std::string_view where);
/// Throws what solve would for the problem and the options, and for the guess's sizes.
template <manifolds::ManifoldWithConnection M>
void validate(const ManifoldObjectProblem<M>& problem, const SolveOptions& options, const Guess& guess, std::string_view where);

/// The checks of verify/ and their verdict (docs/verify.md) on samples of a solution of `problem`
/// by a method of `order`, solved to `tol`, that ended with `status`: on a group the Lie-group
/// kernel's samples (xi in aux), on a manifold the general kernel's (frames, Xi in aux). The
/// resolution is the samples' own: the problem's N is replaced by their steps; on a manifold a
/// problem without frame0 takes the first sampled frame (samples without frames: the problem's
/// default frame). Samples without rows of a result that did
/// not converge: the failing `converged` check alone (verify::unchecked_failure). Throws
/// std::invalid_argument "<where>: ..." for tables of another shape, and on a manifold for a
/// converged result without samples.
template <groups::LieGroup G>
verify::Report verify(const GroupObjectProblem<G>& problem, const Samples& x, int order, double tol, Status status,
                      std::string_view where);
template <manifolds::ManifoldWithConnection M>
verify::Report verify(const ManifoldObjectProblem<M>& problem, const Samples& x, int order, double tol, Status status,
                      std::string_view where);

/// What the samples carry along them (Along) on a group, with the Cartan–Schouten lambda: the
/// transport P and u, and for `lagrangian` (none: null) the energy and the cumulative action.
/// Throws std::invalid_argument as the kernel's along_solution (a non-finite lambda, times that do
/// not increase) and "<where>: ..." for tables of another shape (mu may have no rows without a
/// Lagrangian, xi always). Fewer than two samples: every table empty.
template <groups::LieGroup G>
Along along(const mechanics::ErasedLagrangian<G>* lagrangian, double lambda, const Samples& x, std::string_view where);
/// The same on a manifold for `problem`'s Lagrangian (kernels/manifold/along.hpp): the frames are
/// the samples' own, or where they have none rebuilt from the problem's frame0; mu, Xi and the
/// frames may have no rows.
template <manifolds::ManifoldWithConnection M>
Along along(const ManifoldObjectProblem<M>& problem, const Samples& x, std::string_view where);

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
