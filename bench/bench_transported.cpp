// Benchmarks of the transported-velocity solvers on the paper's six SO(3) cases, and of the cost
// of one forward sweep as N grows (linear in N, memory O(N)). Counters report forward sweeps.
#include <benchmark/benchmark.h>

#include "cartan/transported/continuation.hpp"
#include "cartan/transported/two_level.hpp"
#include "transported/paper_cases.hpp"

namespace {

using cartan::testing::paper_free_body;
using cartan::testing::paper_oscillator;

void report(benchmark::State& state, const auto& solution) {
  if (!solution.converged) state.SkipWithError(solution.message.c_str());
  state.counters["sweeps"] = solution.sweeps;
  state.counters["terminal_error"] = solution.terminal_error;
}

// The paper's two-level scheme (finite-difference LM inner loop, Picard outer loop).
void BM_FreeBody_TwoLevel(benchmark::State& state) {
  const auto p = paper_free_body(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::solve_two_level(p, {.tolerance = 1e-8});
    report(state, s);
  }
}
// Augmented shooting with the analytic (tangent-linear) Jacobian.
void BM_FreeBody_Shooting(benchmark::State& state) {
  const auto p = paper_free_body(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::solve_shooting(p, {.tolerance = 1e-8});
    report(state, s);
  }
}
void BM_FreeBody_ShootingOrder2(benchmark::State& state) {
  const auto p = paper_free_body(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::solve_shooting(p, {.order = cartan::SchemeOrder::Second, .tolerance = 1e-8});
    report(state, s);
  }
}
// The oscillator at T = 12: the default path (continuation in T from T = 3).
void BM_Oscillator_Continuation(benchmark::State& state) {
  const auto p = paper_oscillator(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::solve_continuation_in_T(p, {.shooting = {.tolerance = 1e-6}});
    report(state, s);
  }
}

// One forward sweep with the tangent-linear map (6 directions), N = 10^3 .. 10^6.
void BM_TangentSweep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto p = paper_oscillator(0.5, n, 12.0 * n / 800);
  const cartan::TransportedScheme<cartan::SO3, cartan::SO3Oscillator> scheme(p, cartan::SchemeOrder::First);
  for (auto _ : state) {
    cartan::SweepOutput<cartan::SO3, cartan::SO3Oscillator> out;
    benchmark::DoNotOptimize(cartan::forward_sweep(scheme, Eigen::Vector3d(-1.4, 0.1, 0.1), Eigen::Vector3d::Zero(),
                                                   nullptr, 6, out));
  }
  state.SetComplexityN(n);
}
// A recorded sweep (every node stored: memory O(N)).
void BM_RecordedSweep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto p = paper_oscillator(0.5, n, 12.0 * n / 800);
  const cartan::TransportedScheme<cartan::SO3, cartan::SO3Oscillator> scheme(p, cartan::SchemeOrder::First);
  for (auto _ : state) {
    cartan::TransportedTrajectory<cartan::SO3> trajectory;
    cartan::SweepOutput<cartan::SO3, cartan::SO3Oscillator> out;
    out.trajectory = &trajectory;
    benchmark::DoNotOptimize(cartan::forward_sweep(scheme, Eigen::Vector3d(-1.4, 0.1, 0.1), Eigen::Vector3d::Zero(),
                                                   nullptr, 0, out));
    state.counters["bytes_per_node"] =
        static_cast<double>(sizeof(double) * (1 + 9 + 3 + 3 + 3));
  }
  state.SetComplexityN(n);
}

}  // namespace

// range(0) = 2 lambda: 0, 1, 2 -> lambda = 0, 1/2, 1.
BENCHMARK(BM_FreeBody_TwoLevel)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeBody_Shooting)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeBody_ShootingOrder2)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Oscillator_Continuation)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TangentSweep)->RangeMultiplier(10)->Range(1000, 1000000)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RecordedSweep)->RangeMultiplier(10)->Range(1000, 1000000)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
