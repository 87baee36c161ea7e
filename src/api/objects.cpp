// api::solve, validate, verify and along for problems given as objects (erased.hpp): the kernels'
// compiled solves, verifiers and quantities along a solution (kernels/lie_group/compiled.hpp,
// kernels/manifold/compiled.hpp) with guesses, results and samples in numbers, for every shipped
// group (its built-in models and the erased Lagrangian) and manifold, with the decisions every door
// shares: what a result carries along it, the resolution and (on a manifold) the frame at q0 taken
// from the samples, and the verdict of a failed result without samples.
#include <algorithm>
#include <limits>
#include <optional>
#include <string>

#include "cartan/api/erased.hpp"
#include "cartan/errors.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "samples.hpp"

namespace cartan::api {

namespace {

int steps_of(const Samples& x) { return std::max<int>(1, static_cast<int>(x.t.size()) - 1); }

/// `numbers` as a Value of their count (row-major), or none when empty; throws
/// "<where>: <name> = (k numbers) must have <size> numbers (<what>)" for another count.
template <class Value>
std::optional<Value> guess_value(const std::vector<double>& numbers, const char* name, std::string_view what,
                                 std::string_view where) {
  if (numbers.empty()) return std::nullopt;
  const auto size = static_cast<std::size_t>(Value::SizeAtCompileTime);
  if (numbers.size() != size) {
    throw_invalid(where, name, "(" + std::to_string(numbers.size()) + " numbers)",
                  "must have " + std::to_string(size) + " numbers (" + std::string(what) + ")");
  }
  return value_of_numbers<Value>(numbers);
}

/// Throws "<where>: <name> = (k numbers) is a guess of the <kernel>" when `numbers` are given.
void refuse_guess(const std::vector<double>& numbers, const char* name, std::string_view why, std::string_view where) {
  if (!numbers.empty()) throw_invalid(where, name, "(" + std::to_string(numbers.size()) + " numbers)", why);
}

template <groups::LieGroup G>
transported::SolveGuess<G> group_guess(const Guess& guess, std::string_view where) {
  refuse_guess(guess.Xi0, "Xi0", "is a guess of the general kernel's Xi, not of the Lie-group kernel's xi (give xi0)", where);
  transported::SolveGuess<G> out;
  out.v0 = guess_value<groups::TangentOf<G>>(guess.v0, "v0", "a guess of v(0)", where);
  out.xi0 = guess_value<groups::CovectorOf<G>>(guess.xi0, "xi0", "a guess of xi(0)", where);
  if (guess.trajectory) {
    Samples x = *guess.trajectory;
    if (x.mu.rows() == 0) x.mu = Table::Zero(x.t.size(), G::kDim);  // not needed of a guess
    detail::check_samples(x, groups::ElementOf<G>::SizeAtCompileTime, G::kDim, G::kDim, std::string(where) + ": guess");
    out.trajectory = detail::lie_trajectory<G>(x);
  }
  return out;
}

template <manifolds::ManifoldWithConnection M>
general::GeneralGuess<M> manifold_guess(const Guess& guess, std::string_view where) {
  refuse_guess(guess.xi0, "xi0", "is a guess of the Lie-group kernel's xi, not of the general kernel's Xi (give Xi0)", where);
  general::GeneralGuess<M> out;
  out.v0 = guess_value<manifolds::ComponentsOf<M>>(guess.v0, "v0", "a guess of v(0) in the frame at q0", where);
  out.Xi0 = guess_value<manifolds::ComponentMatrixOf<M>>(guess.Xi0, "Xi0", "a guess of Xi(0), row-major", where);
  if (guess.trajectory) {
    constexpr Eigen::Index n = M::kDim;
    detail::check_samples(*guess.trajectory, manifolds::PointOf<M>::SizeAtCompileTime, n, n * n, std::string(where) + ": guess",
                          manifolds::FrameOf<M>::SizeAtCompileTime);
    out.trajectory = detail::general_trajectory<M>(*guess.trajectory);
  }
  return out;
}

/// A kernel's result in numbers: its ResultCore moved, the samples, the unknowns.
template <class Solution>
Result result_of(Solution&& s, bool lie_kernel) {
  Result r;
  static_cast<ResultCore&>(r) = std::move(static_cast<ResultCore&>(s));
  r.lie_kernel = lie_kernel;
  r.samples = detail::samples_of(s.trajectory);
  r.v0 = s.v0;
  if constexpr (requires { s.xi0; }) {
    r.aux0 = s.xi0;
  } else {
    r.aux0 = detail::rows(std::vector{s.Xi0}).row(0).transpose();
  }
  return r;
}

}  // namespace

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
Result solve(const transported::TransportedProblem<G, L>& problem, const SolveOptions& options, const Guess& guess,
             SolveOutputs outputs, std::string_view where) {
  transported::TransportedSolution<G> s = transported::solve(problem, options, group_guess<G>(guess, where));
  std::optional<Along> along;
  if (outputs.along && !stopped_on_request(s.status)) {
    along = detail::along_of<G>(transported::along_solution<G>(mechanics::ErasedLagrangian<G>(problem.lagrangian), problem.lambda,
                                                               s.trajectory));
  }
  Result r = result_of(std::move(s), true);
  r.along = std::move(along);
  return r;
}

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void validate(const transported::TransportedProblem<G, L>& problem, const SolveOptions& options, const Guess& guess,
              std::string_view where) {
  transported::validate(problem, options, group_guess<G>(guess, where));
}

template <manifolds::ManifoldWithConnection M>
Result solve(const ManifoldObjectProblem<M>& problem, const SolveOptions& options, const Guess& guess, SolveOutputs outputs,
             std::string_view where) {
  general::GeneralSolution<M> s = general::solve(problem, options, manifold_guess<M>(guess, where));
  std::optional<general::GeneralAlong<M>> along;
  if (!stopped_on_request(s.status) && s.trajectory.t.size() >= 2) along = general::along_general(problem, s.trajectory);
  Result r = result_of(std::move(s), false);
  r.action = along ? along->action.back() : std::numeric_limits<double>::quiet_NaN();
  if (along && outputs.along) r.along = detail::along_of<M>(*along);
  return r;
}

template <manifolds::ManifoldWithConnection M>
void validate(const ManifoldObjectProblem<M>& problem, const SolveOptions& options, const Guess& guess, std::string_view where) {
  (void)manifold_guess<M>(guess, where);
  problem.validate();
  options.validate();
}

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
  if (!posed.frame0 && x.frames.rows() > 0) posed.frame0 = value_of_row<manifolds::FrameOf<M>>(x.frames, 0);
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

#define CARTAN_API_SOLVE_ON_GROUP(G, L)                                                                              \
  template Result solve<G, L>(const transported::TransportedProblem<G, L>&, const SolveOptions&, const Guess&, SolveOutputs, \
                              std::string_view);                                                                       \
  template void validate<G, L>(const transported::TransportedProblem<G, L>&, const SolveOptions&, const Guess&, std::string_view);
CARTAN_TRANSPORTED_BUILTIN_MODELS(CARTAN_API_SOLVE_ON_GROUP)
#define CARTAN_API_SOLVE_ERASED_ON_GROUP(G) CARTAN_API_SOLVE_ON_GROUP(G, ::cartan::mechanics::ErasedLagrangian<G>)
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_API_SOLVE_ERASED_ON_GROUP)
#undef CARTAN_API_SOLVE_ERASED_ON_GROUP
#undef CARTAN_API_SOLVE_ON_GROUP
#define CARTAN_API_OBJECTS_ON_GROUP(G)                                                                                  \
  template verify::Report verify<G>(const GroupObjectProblem<G>&, const Samples&, int, double, Status, std::string_view); \
  template Along along<G>(const mechanics::ErasedLagrangian<G>*, double, const Samples&, std::string_view);
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_API_OBJECTS_ON_GROUP)
#undef CARTAN_API_OBJECTS_ON_GROUP
#define CARTAN_API_OBJECTS_ON_MANIFOLD(M)                                                                                  \
  template verify::Report verify<M>(const ManifoldObjectProblem<M>&, const Samples&, int, double, Status, std::string_view); \
  template Along along<M>(const ManifoldObjectProblem<M>&, const Samples&, std::string_view);                               \
  template Result solve<M>(const ManifoldObjectProblem<M>&, const SolveOptions&, const Guess&, SolveOutputs, std::string_view); \
  template void validate<M>(const ManifoldObjectProblem<M>&, const SolveOptions&, const Guess&, std::string_view);
CARTAN_GENERAL_SHIPPED_MANIFOLDS(CARTAN_API_OBJECTS_ON_MANIFOLD)
#undef CARTAN_API_OBJECTS_ON_MANIFOLD

}  // namespace cartan::api
