// The cost of generality, side by side in one process on the paper's free body (lambda = 0.3,
// T = 5, N = 1000): one primal sweep of the Lie-group scheme (kernels/lie_group/scheme.hpp) against the
// general scheme (kernels/manifold/scheme.hpp) on the same Cartan–Schouten connection given as a
// GroupManifold, with the constant-components fast path and without it (frame components
// recomputed from Gamma at every node), and the general tangent-linear sweep (12 directions); and
// whole shooting solves, the Lie-group solver's against the general one's with its tangent-linear
// Jacobian (argument 1) or forward differences (0), on the Cartan–Schouten connection and on the
// Levi-Civita connection of the inertia (not parallel: frame components recomputed at every node);
// and the typed general::solve against the library's compiled one for the erased Lagrangian.
// bench/README.md, "General connections", has the ratios.
#include <benchmark/benchmark.h>

#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/methods/solve.hpp"  // the typed solve, against the erased one
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/methods/lie_group/shooting.hpp"
#include "kernels/manifold/general_cases.hpp"  // paper cases, WithoutFastPath

namespace {

using namespace cartan;
using SO3Manifold = manifolds::GroupManifold<groups::SO3>;
using Lagrangian = general::KineticPotential<SO3Manifold>;
constexpr double kLambda = 0.3;

template <class M>
general::GeneralProblem<M, general::KineticPotential<M>> general_problem(const M& manifold) {
  const auto p = testing::paper_free_body(kLambda, 1000, 5);
  return {manifold, general::KineticPotential<M>(testing::paper_inertia()), p.T, p.N, p.g0, p.gT, std::nullopt};
}

const Eigen::Vector3d kV0(-0.28, 0.02, 0.02);

void BM_Sweep_LieGroupScheme(benchmark::State& state) {
  const transported::TransportedScheme<groups::SO3, mechanics::RigidBody> scheme(testing::paper_free_body(kLambda, 1000, 5),
                                                                                 cartan::SchemeOrder::First);
  for (auto _ : state) {
    transported::SweepOutput<groups::SO3, mechanics::RigidBody> out;
    if (!transported::forward_sweep(scheme, kV0, Eigen::Vector3d::Zero(), nullptr, 0, out)) state.SkipWithError(out.failure.c_str());
    benchmark::DoNotOptimize(out);
  }
}

template <class M>
void sweep_general(benchmark::State& state, const M& manifold) {
  const general::GeneralScheme<M, general::KineticPotential<M>> scheme(general_problem(manifold), cartan::SchemeOrder::First);
  std::string failure;
  for (auto _ : state) {
    const auto last = general::general_sweep(scheme, kV0, Eigen::Matrix3d::Zero().eval(), failure);
    if (!last) state.SkipWithError(failure.c_str());
    benchmark::DoNotOptimize(last);
  }
}
void BM_Sweep_GeneralFastPath(benchmark::State& state) { sweep_general(state, SO3Manifold::cartan_schouten(kLambda)); }
void BM_Sweep_GeneralRecomputedComponents(benchmark::State& state) {
  sweep_general(state, testing::WithoutFastPath<SO3Manifold>{SO3Manifold::cartan_schouten(kLambda)});
}

void BM_TangentSweep_GeneralFastPath(benchmark::State& state) {
  using L = general::KineticPotential<SO3Manifold>;
  const general::GeneralScheme<SO3Manifold, L> scheme(general_problem(SO3Manifold::cartan_schouten(kLambda)),
                                                      cartan::SchemeOrder::First);
  const general::GeneralSchemeTangent<SO3Manifold, L> tangent(scheme);
  std::string failure;
  Eigen::MatrixXd jacobian;
  for (auto _ : state) {
    const auto last = general::general_sweep(scheme, kV0, Eigen::Matrix3d::Zero().eval(), failure,
                                             static_cast<general::GeneralTrajectory<SO3Manifold>*>(nullptr), &tangent,
                                             &jacobian);
    if (!last) state.SkipWithError(failure.c_str());
    benchmark::DoNotOptimize(jacobian);
  }
}

void BM_Solve_LieGroupShooting(benchmark::State& state) {
  const auto p = testing::paper_free_body(kLambda, 1000, 5);
  for (auto _ : state) {
    const auto s = transported::solve_shooting(p, {.tolerance = 1e-10});
    if (!s.converged()) state.SkipWithError(s.message.c_str());
    state.counters["sweeps"] = s.sweeps;
  }
}
template <class M>
void solve_general(benchmark::State& state, const M& manifold) {
  const auto p = general_problem(manifold);
  cartan::ShootingOptions options;
  options.tolerance = 1e-10;
  options.analytic_jacobian = state.range(0) == 1;
  for (auto _ : state) {
    const auto s = general::solve_general_shooting(p, options);
    if (!s.converged()) state.SkipWithError(s.message.c_str());
    state.counters["sweeps"] = s.sweeps;
  }
}
void BM_Solve_GeneralShootingFastPath(benchmark::State& state) {
  solve_general(state, SO3Manifold::cartan_schouten(kLambda));
}
void BM_Solve_GeneralShootingLeviCivita(benchmark::State& state) {
  solve_general(state, SO3Manifold::levi_civita(testing::paper_inertia()));
}

/// general::solve (shooting) on p: the typed instantiation of this unit, or the library's compiled
/// one when L is the erased Lagrangian (kernels/manifold/compiled.hpp).
template <class L>
void solve_with(benchmark::State& state, const general::GeneralProblem<SO3Manifold, L>& p) {
  cartan::SolveOptions options;
  options.method = cartan::Method::Shooting;
  for (auto _ : state) {
    const auto s = general::solve(p, options);
    if (!s.converged()) state.SkipWithError(s.message.c_str());
    state.counters["sweeps"] = s.sweeps;
  }
}
/// The cost of the erased Lagrangian (one indirect call per evaluation of l, mu, v, zeta or the
/// second derivatives) under the Levi-Civita connection of the inertia: argument 0 the typed
/// solve, 1 the compiled one behind general::ErasedLagrangian (what the CLI and Python call).
void BM_Solve_LeviCivitaTypedOrErased(benchmark::State& state) {
  const auto typed = general_problem(SO3Manifold::levi_civita(testing::paper_inertia()));
  if (state.range(0) == 0) return solve_with(state, typed);
  solve_with(state, general::ErasedProblem<SO3Manifold>{typed.manifold, general::ErasedLagrangian<SO3Manifold>(typed.lagrangian),
                                                        typed.T, typed.N, typed.q0, typed.qT, std::nullopt});
}

/// One door, one solve (issue 44): the paper's free body through its model (argument 0: the
/// library's compiled solve of mechanics::RigidBody, kernels/lie_group/compiled.hpp) and as the particle
/// on GroupManifold<SO3>::cartan_schouten (1: the compiled general::solve of the erased
/// KineticPotential, which runs the Lie-group kernel with the Hessian structure the erased
/// Lagrangian reports). Goal: 1 within 1.1 of 0.
void BM_Solve_CartanSchoutenModelOrManifold(benchmark::State& state) {
  cartan::SolveOptions options;
  options.method = cartan::Method::Shooting;
  if (state.range(0) == 0) {
    const auto p = testing::paper_free_body(kLambda, 1000, 5);
    for (auto _ : state) {
      const auto s = transported::solve(p, options);
      if (!s.converged()) state.SkipWithError(s.message.c_str());
      state.counters["sweeps"] = s.sweeps;
    }
    return;
  }
  const auto typed = general_problem(SO3Manifold::cartan_schouten(kLambda));
  solve_with(state, general::ErasedProblem<SO3Manifold>{typed.manifold, general::ErasedLagrangian<SO3Manifold>(typed.lagrangian),
                                                        typed.T, typed.N, typed.q0, typed.qT, std::nullopt});
}

}  // namespace

BENCHMARK(BM_Sweep_LieGroupScheme)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Sweep_GeneralFastPath)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Sweep_GeneralRecomputedComponents)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TangentSweep_GeneralFastPath)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Solve_LieGroupShooting)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Solve_GeneralShootingFastPath)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Solve_GeneralShootingLeviCivita)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Solve_LeviCivitaTypedOrErased)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Solve_CartanSchoutenModelOrManifold)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
