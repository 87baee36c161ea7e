// The library's compiled solves (src/kernels/lie_group/, src/kernels/manifold/: the explicit instantiations that
// CMakeLists.txt compiles in unity groups), as the CLI and Python reach them: transported::solve of
// the paper's free body and oscillator (built-in models, extern templates in methods/lie_group/solve.hpp)
// and general::solve of the erased Lagrangian (kernels/manifold/compiled.hpp) on SO(3) with Levi-Civita and
// with Cartan–Schouten (the Lie-group kernel), on S^2 and on R^3. This unit instantiates no solver:
// linked against libraries compiled differently (unity groups or not, compiler flags), it measures
// their code alone (bench/README.md "Build time": the large-unit inlining cap).
#include <benchmark/benchmark.h>

#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/methods/lie_group/solve.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace {

using namespace cartan;
using SO3Manifold = manifolds::GroupManifold<groups::SO3>;

template <class Solve>
void run(benchmark::State& state, Solve&& solve) {
  for (auto _ : state) {
    const auto s = solve();
    if (!s.converged()) state.SkipWithError(s.message.c_str());
    benchmark::DoNotOptimize(s.v0);
  }
}

template <class M>
general::ErasedProblem<M> erased_kinetic(const M& manifold, const typename general::KineticPotential<M>::Inertia& inertia,
                                        double T, int N, const typename M::Point& q0, const typename M::Point& qT) {
  return general::erased(general::GeneralProblem<M, general::KineticPotential<M>>{
      manifold, general::KineticPotential<M>(inertia), T, N, q0, qT, std::nullopt});
}

void BM_Transported_FreeBody(benchmark::State& state) {
  const auto p = testing::paper_free_body(0.5);
  run(state, [&] { return transported::solve(p); });
}

void BM_Transported_Oscillator(benchmark::State& state) {
  const auto p = testing::paper_oscillator(0.5);
  run(state, [&] { return transported::solve(p); });
}

/// The free body's endpoints (lambda = 1/2, N = 1000, T = 50) on SO(3) as a manifold: argument 0
/// Levi-Civita of the inertia (the general kernel), 1 Cartan–Schouten (the Lie-group kernel).
void BM_General_SO3(benchmark::State& state) {
  const auto f = testing::paper_free_body(0.5);
  const SO3Manifold manifold = state.range(0) == 0 ? SO3Manifold::levi_civita(testing::paper_inertia())
                                                   : SO3Manifold::cartan_schouten(0.5);
  const auto p = erased_kinetic(manifold, testing::paper_inertia(), f.T, f.N, f.g0, f.gT);
  run(state, [&] { return general::solve(p); });
}

void BM_General_Sphere(benchmark::State& state) {
  const auto p = erased_kinetic(manifolds::Sphere{}, Eigen::Matrix2d::Identity(), 3.0, 20000,
                                manifolds::sphere_point({1, 0, 0.2}), manifolds::sphere_point({0.1, 1, 0.5}));
  run(state, [&] { return general::solve(p); });
}

void BM_General_R3(benchmark::State& state) {
  const auto p = erased_kinetic(manifolds::Euclidean<3>{}, Eigen::Matrix3d::Identity(), 2.0, 20000,
                                Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3));
  run(state, [&] { return general::solve(p); });
}

}  // namespace

BENCHMARK(BM_Transported_FreeBody)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Transported_Oscillator)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_General_SO3)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_General_Sphere)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_General_R3)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
