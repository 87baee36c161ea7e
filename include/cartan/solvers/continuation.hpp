#pragma once
// Continuation paths, written once for every problem family with shooting and compiled once
// (src/solvers/continuation.cpp): the Lie-group kernel's TransportedProblem
// (methods/lie_group/continuation.hpp), the general GeneralProblem (methods/manifold/solve.hpp), the Lie-group
// kernel inside the general solve (methods/lie_group_as_manifold.hpp). ShootingFamily<Problem> says how to
// shoot one problem of a family and where its unknowns (a velocity and an auxiliary: (v0, xi0)
// or (v0, Xi0)) live in a solution; FamilyPath (below) hands a family to the compiled path as a
// ShootingPath, its solutions as PathResults. The path itself (docs/paper-notes.md#erratum-4):
//  * in T: halve the horizon until shooting from the guess converges, then lengthen it step by
//    step (same step size h, so N scales with T), each solve starting from the previous
//    unknowns; a failed stage halves the increment;
//  * any scalar parameter (lambda: methods/lie_group/continuation.hpp) by continue_parameter.
// A failed path returns the best iterate *of the requested problem*, never a stage's trajectory
// at another T or lambda, and its message says where the path stopped.

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "cartan/principle/options.hpp"
#include "cartan/principle/result.hpp"

namespace cartan::solvers {

/// One solution of a family on a path: its ResultCore and its unknowns as numbers (an auxiliary
/// matrix column-major). Moved, never copied (a trajectory may hold 0.3 GB).
class PathResult {
 public:
  virtual ~PathResult() = default;
  virtual ResultCore& core() = 0;
  virtual const ResultCore& core() const = 0;
  virtual Eigen::VectorXd velocity() const = 0;
  virtual Eigen::VectorXd auxiliary() const = 0;
  virtual bool has_trajectory() const = 0;
  /// A copy (the default strategy keeps a failed shooting for continuation's first stage).
  virtual std::unique_ptr<PathResult> clone() const = 0;
};
using PathResultPtr = std::unique_ptr<PathResult>;

/// A problem family along a scalar parameter p (the horizon T, or lambda): the problem at p is
/// the family's, shot from given unknowns. Sizes are the family's own (typed) norms, so that the
/// compiled path computes what the typed one did to the bit (docs/design/one-core.md, R1).
class ShootingPath {
 public:
  virtual ~ShootingPath() = default;
  virtual PathResultPtr shoot(double p, const ShootingOptions& options, const Eigen::VectorXd& velocity,
                              const Eigen::VectorXd& auxiliary) const = 0;
  virtual PathResultPtr empty() const = 0;                ///< a result without trajectory
  virtual Eigen::VectorXd guess(double p) const = 0;      ///< the family's guess of the velocity at p
  virtual Eigen::VectorXd zero_auxiliary() const = 0;
  virtual double auxiliary_scale(double p) const = 0;     ///< the unit of the auxiliary at p
  virtual double velocity_norm(const Eigen::VectorXd& v) const = 0;
  virtual double auxiliary_norm(const Eigen::VectorXd& a) const = 0;
  /// Whether a result's inner_iterations count along a path (the general kernel reports its last
  /// solve's: docs/design/one-core.md, D8).
  virtual bool sums_inner_iterations() const = 0;
};

/// Where a continuation path stopped.
struct PathEnd {
  double reached = 0;   ///< the parameter of the last accepted stage
  int stages = 0;
  bool complete = false;
  std::string why;      ///< empty when complete
};

/// The size of a result's terminal residual in the units of the convergence test, for an
/// auxiliary of unit `auxiliary_scale` (a result with a trajectory).
inline double scaled_residual(const ResultCore& s, double auxiliary_scale) {
  return std::hypot(s.terminal_error, s.xi_terminal / auxiliary_scale);
}

/// Walks the parameter from `from` to `to` along one solution branch, from `current` (a solution
/// at `from`, replaced by the last accepted stage's). Predictor: the secant through the last two
/// accepted solutions (the previous solution for the first stage). Corrector: shooting from the
/// prediction, abandoned at once when the residual at the prediction exceeds max_stage_residual,
/// and to stage_tolerance except at the last stage. A stage is accepted when it converges *and*
/// lands within max_correction of the prediction (in the relative norm of `distance`); otherwise
/// the increment is halved. On a smooth branch the correction shrinks with the increment
/// (quadratically after the first stage), so a small enough stage is always accepted; a corrector
/// that converges far from the prediction has jumped to another branch (bench/README.md,
/// "continuation acceptance"). Accumulates work into `current`. Progress reports name the stage:
/// "continuation in <parameter>, stage k at <parameter> = s".
PathEnd continue_parameter(const ShootingPath& path, double from, double to, PathResultPtr& current,
                           const ContinuationOptions& options, std::string_view parameter);

/// A solution's unknowns as numbers.
struct Unknowns {
  Eigen::VectorXd velocity, auxiliary;
};

/// The failure result of a continuation of the problem at `requested`: the better (smaller scaled
/// residual) of `direct` (an attempt on the requested problem, may be null) and a solve of the
/// requested problem from the unknowns of the last stage reached (if any); status
/// ContinuationFailed (or Interrupted), all work counted.
PathResultPtr best_iterate(const ShootingPath& path, double requested, PathResultPtr direct,
                           const std::optional<Unknowns>& last_stage, const ContinuationOptions& options, int sweeps,
                           int iterations);

/// Continuation in T of the problem at `T` (the path's parameter is the horizon), from the given
/// guesses (the velocity scaled by T / T' at a shorter horizon T'). `failed_direct`, when not
/// null, is a failed attempt at the full horizon from the same guess, not repeated.
PathResultPtr continue_in_T(const ShootingPath& path, double T, const ContinuationOptions& options,
                            const std::optional<Eigen::VectorXd>& velocity_guess,
                            const std::optional<Eigen::VectorXd>& auxiliary_guess, PathResultPtr failed_direct);

/// Continuation in `parameter` (lambda) of the problems `path` makes, from `start` (a solve at
/// `from`, e.g. continuation in T's at lambda_start) to `to`, the requested problem's value; the
/// result's words name the path ("continued in lambda from lambda = ... [start's branch] (k
/// stages)"), its time counts from `started`. A start that failed gives the best iterate of the
/// requested problem: itself if from == to, else none.
PathResultPtr continue_in_parameter(const ShootingPath& path, double from, double to, PathResultPtr start,
                                    const ContinuationOptions& options, std::string_view parameter,
                                    std::chrono::steady_clock::time_point started);

/// How continuation drives shooting on one problem family (header comment): the types Solution,
/// Velocity, Auxiliary; shoot(problem, options, velocity, auxiliary); velocity(s), auxiliary(s),
/// guess(problem), auxiliary_scale(problem); kSumsInnerIterations (ShootingPath::sums_inner_iterations).
template <class Problem>
struct ShootingFamily;

namespace detail {

/// A fixed-size vector or matrix as numbers (column-major), and back.
template <class X>
Eigen::VectorXd flat(const X& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}
template <class X>
X typed(const Eigen::VectorXd& numbers) {
  X x;
  Eigen::Map<Eigen::VectorXd>(x.data(), x.size()) = numbers;
  return x;
}

/// A family's solution as a PathResult.
template <class Family>
struct ResultOf final : PathResult {
  typename Family::Solution value;

  explicit ResultOf(typename Family::Solution s) : value(std::move(s)) {}
  ResultCore& core() override { return value; }
  const ResultCore& core() const override { return value; }
  Eigen::VectorXd velocity() const override { return flat(Family::velocity(value)); }
  Eigen::VectorXd auxiliary() const override { return flat(Family::auxiliary(value)); }
  bool has_trajectory() const override { return !value.trajectory.t.empty(); }
  std::unique_ptr<PathResult> clone() const override { return std::make_unique<ResultOf>(value); }
};

}  // namespace detail

/// A solution of the family of `Problem` as a PathResult, and back.
template <class Problem, class Solution = typename ShootingFamily<Problem>::Solution>
PathResultPtr wrap(Solution s) {
  return std::make_unique<detail::ResultOf<ShootingFamily<Problem>>>(std::move(s));
}
template <class Problem>
typename ShootingFamily<Problem>::Solution take(PathResultPtr r) {
  auto* of = dynamic_cast<detail::ResultOf<ShootingFamily<Problem>>*>(r.get());
  if (of == nullptr) throw std::logic_error("solvers::take: a result of another family");
  return std::move(of->value);
}

/// The family of `Problem` along the parameter p, make(p) the problem at p.
template <class Problem, class Make>
class FamilyPath final : public ShootingPath {
 public:
  using Family = ShootingFamily<Problem>;
  using Solution = typename Family::Solution;
  using Velocity = typename Family::Velocity;
  using Auxiliary = typename Family::Auxiliary;

  explicit FamilyPath(Make make) : make_(std::move(make)) {}

  static PathResultPtr wrap(Solution s) { return solvers::wrap<Problem>(std::move(s)); }
  /// The solution a PathResult of this family holds, moved out.
  static Solution take(PathResultPtr r) { return solvers::take<Problem>(std::move(r)); }

  PathResultPtr shoot(double p, const ShootingOptions& options, const Eigen::VectorXd& velocity,
                      const Eigen::VectorXd& auxiliary) const override {
    return wrap(Family::shoot(make_(p), options, detail::typed<Velocity>(velocity), detail::typed<Auxiliary>(auxiliary)));
  }
  PathResultPtr empty() const override { return wrap(Solution{}); }
  Eigen::VectorXd guess(double p) const override { return detail::flat(Family::guess(make_(p))); }
  Eigen::VectorXd zero_auxiliary() const override { return detail::flat(Auxiliary(Auxiliary::Zero())); }
  double auxiliary_scale(double p) const override { return Family::auxiliary_scale(make_(p)); }
  double velocity_norm(const Eigen::VectorXd& v) const override { return detail::typed<Velocity>(v).norm(); }
  double auxiliary_norm(const Eigen::VectorXd& a) const override { return detail::typed<Auxiliary>(a).norm(); }
  bool sums_inner_iterations() const override { return Family::kSumsInnerIterations; }

 private:
  Make make_;
};

template <class Problem, class Make>
FamilyPath<Problem, Make> family_path(Make make) {
  return FamilyPath<Problem, Make>(std::move(make));
}

namespace detail {

/// The problem of the T path at horizon T' (same step h = T / N, N' = round(T' / h) >= 1; exactly
/// `problem` at T).
template <class Problem>
auto horizon_family(const Problem& problem) {
  return family_path<Problem>([&problem, h = problem.step()](double horizon) {
    Problem p = problem;
    p.T = horizon;
    p.N = std::max(1, static_cast<int>(std::lround(horizon / h)));
    if (horizon == problem.T) p.N = problem.N;
    return p;
  });
}

/// continue_in_T on a family (solve_continuation_in_T, methods/lie_group/continuation.hpp;
/// methods/manifold/solve.hpp). `failed_direct`, when not null, is moved from.
template <class Problem, class Solution = typename ShootingFamily<Problem>::Solution>
Solution continue_in_T(const Problem& problem, const ContinuationOptions& options,
                       std::optional<typename ShootingFamily<Problem>::Velocity> v0_guess,
                       std::optional<typename ShootingFamily<Problem>::Auxiliary> aux_guess,
                       Solution* failed_direct) {
  const auto path = horizon_family(problem);
  std::optional<Eigen::VectorXd> v, a;
  if (v0_guess) v = flat(*v0_guess);
  if (aux_guess) a = flat(*aux_guess);
  return path.take(solvers::continue_in_T(path, problem.T, options, v, a,
                                          failed_direct != nullptr ? path.wrap(std::move(*failed_direct)) : nullptr));
}

/// Continuation in lambda on a family (solve_continuation_in_lambda, methods/lie_group/continuation.hpp;
/// the Lie-group kernel inside the general solve, methods/lie_group_as_manifold.hpp): from the solution at
/// lambda = `start` (continue_in_T's, directly from the geodesic guess when that converges) to
/// the problem's lambda.
template <class Problem, class Solution = typename ShootingFamily<Problem>::Solution>
Solution continue_in_lambda(const Problem& problem, double start, const ContinuationOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  auto make = [&problem](double lambda) {
    Problem p = problem;
    p.lambda = lambda;
    return p;
  };
  const auto path = family_path<Problem>(std::cref(make));
  Solution first = continue_in_T(make(start), options, std::nullopt, std::nullopt, static_cast<Solution*>(nullptr));
  return path.take(
      solvers::continue_in_parameter(path, start, problem.lambda, path.wrap(std::move(first)), options, "lambda", started));
}

}  // namespace detail

}  // namespace cartan::solvers
