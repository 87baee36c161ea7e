#pragma once
// The collocation solution of the transported-velocity BVP (eq:reduced-system) in the form the
// shooting solvers return (TransportedSolution, kernels/lie_group/solution.hpp): g, v, mu, xi at the
// final mesh or at uniform output times, read from the solution's cubic interpolant. One
// function per formulation: the closed-form H3 system (heisenberg_collocation.hpp, xi integrated
// along the solution) and the generic one (collocation_system.hpp, xi a state).

#include <chrono>
#include <functional>
#include <string>

#include "cartan/errors.hpp"
#include "cartan/kernels/lie_group/collocation_system.hpp"
#include "cartan/kernels/lie_group/heisenberg_collocation.hpp"
#include "cartan/kernels/lie_group/solution.hpp"
#include "cartan/methods/lie_group/continuation.hpp"
#include "cartan/solvers/collocation.hpp"

namespace cartan::transported {

using solvers::output_times;

/// The transported state (g, v, xi) at output time j, given the interpolated state y there.
template <groups::LieGroup G>
struct TransportedState {
  groups::ElementOf<G> g;
  groups::TangentOf<G> v;
  groups::CovectorOf<G> xi;
};
template <groups::LieGroup G>
using StateReader = std::function<TransportedState<G>(Eigen::Index j, const Eigen::VectorXd& y)>;

/// The solution at `times` with mu = momentum(t, g, v), the endpoint errors |log(gT^{-1} g(T))|
/// and |xi(T)| (times must end at T), and the counters: outer = mesh refinements, inner = Newton
/// iterations, sweeps = Jacobian evaluations (as `cartan solve --method collocation`).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> collocation_solution(const TransportedProblem<G, L>& problem, const numerics::BvpResult& result,
                                            const Eigen::VectorXd& times, const StateReader<G>& read) {
  TransportedSolution<G> s;
  s.status = result.status;
  s.message = result.message;
  s.method = Method::Collocation;
  s.branch = "direct from the geodesic guess on a uniform mesh of N intervals";
  s.order = kCollocationOrder;
  const numerics::CubicHermite interpolant = result.interpolant();
  auto& tr = s.trajectory;
  tr.reserve(static_cast<std::size_t>(times.size()));
  for (Eigen::Index j = 0; j < times.size(); ++j) {
    const TransportedState<G> x = read(j, interpolant.value(times[j]));
    tr.t.push_back(times[j]);
    tr.g.push_back(x.g);
    tr.v.push_back(x.v);
    tr.mu.push_back(problem.lagrangian.momentum(times[j], x.g, x.v));
    tr.xi.push_back(x.xi);
  }
  if (!tr.t.empty()) {
    s.v0 = tr.v.front();
    s.xi0 = tr.xi.front();
    s.terminal_error = groups::log_between<G>(problem.gT, tr.g.back()).norm();
    s.xi_terminal = tr.xi.back().norm();
  }
  s.collocation = CollocationReport{static_cast<int>(result.t.size()), result.max_rms_residual};
  s.outer_iterations = result.refinements;
  s.inner_iterations = result.newton_iterations;
  s.sweeps = result.jacobian_evaluations;
  return s;
}

/// H3 by the closed-form system (solve_heisenberg_collocation), xi by exact quadrature. `raw`,
/// when given, receives the collocation result itself (mesh, residuals).
template <mechanics::Potential<groups::Heisenberg> V>
TransportedSolution<groups::Heisenberg> solve_heisenberg_transported(const HeisenbergNaturalProblem<V>& problem,
                                                             const numerics::CollocationOptions& options, int samples) {
  check_samples(samples);
  double seconds = 0;
  const numerics::BvpResult r = timed(seconds, [&] { return solve_heisenberg_collocation(problem, options); });
  const Eigen::VectorXd times = output_times(r, samples, problem.T);
  const Eigen::MatrixXd xi = heisenberg_xi(problem, r, times);
  auto s = collocation_solution<groups::Heisenberg>(problem, r, times, [&](Eigen::Index j, const Eigen::VectorXd& y) {
    return TransportedState<groups::Heisenberg>{y.head<3>(), y.segment<3>(3), xi.col(j)};
  });
  s.solve_time_s = seconds;
  return s;
}

/// Any group by the generic system (TransportedCollocation), xi read from the state, through
/// the collocation driver of every kernel (solvers::collocate): from the given trajectory (times
/// from 0 to T) or the geodesic guess, by the adaptive solver; with a `fallback` (T, or lambda
/// from lambda = 0), Newton must first converge on the start's mesh, else the start is the
/// order-2 shooting solution that `discrete` (the Lie-group kernel of this problem and guess,
/// methods/lie_group/solve.hpp) finds by that continuation, whose solution branch collocation then
/// refines to the continuous solution; `branch` says which. Counters are summed over every run.
template <groups::LieGroup G, mechanics::Potential<G> V>
TransportedSolution<G> solve_transported_by_collocation(const TransportedProblem<G, mechanics::NaturalLagrangian<G, V>>& problem,
                                                        const numerics::CollocationOptions& options, int samples,
                                                        Continuation fallback, const TransportedTrajectory<G>* guess,
                                                        solvers::StrategyKernel& discrete) {
  using C = TransportedCollocation<G, V>;
  using Problem = TransportedProblem<G, mechanics::NaturalLagrangian<G, V>>;
  check_samples(samples);
  problem.validate();
  struct Continuous final : solvers::ContinuousProblem {
    const Problem& problem;
    const TransportedTrajectory<G>* guess;
    Continuous(const Problem& p, const TransportedTrajectory<G>* g) : problem(p), guess(g) {}
    numerics::BvpSystem system() const override { return C::system(problem); }
    bool start(Eigen::VectorXd& t, Eigen::MatrixXd& y) const override {
      if (guess == nullptr) {
        C::geodesic_guess(problem, t, y);
        return false;
      }
      C::guess_from(problem, *guess, t, y);
      return true;
    }
    void start_from(solvers::PathResultPtr shooting, Eigen::VectorXd& t, Eigen::MatrixXd& y) const override {
      C::guess_from(problem, solvers::take<Problem>(std::move(shooting)).trajectory, t, y);
    }
    bool starts_on_mesh() const override { return false; }
  };
  double seconds = 0;
  const solvers::Collocated c =
      timed(seconds, [&] { return solvers::collocate(Continuous(problem, guess), discrete, fallback, options); });
  const numerics::BvpResult& r = c.result;
  auto s = collocation_solution<G>(problem, r, output_times(r, samples, problem.T),
                                   [](Eigen::Index, const Eigen::VectorXd& y) {
                                     return TransportedState<G>{C::element(y, C::kG),
                                                                y.template segment<C::kDim>(C::kV),
                                                                y.template segment<C::kDim>(C::kXi)};
                                   });
  s.branch = c.branch;
  s.sweeps += c.shooting_sweeps;
  s.solve_time_s = seconds;
  if constexpr (std::same_as<G, groups::SO3>) s.collocation->group_defect = C::orthogonality_defect(r);
  return s;
}

}  // namespace cartan::transported
