// Benchmarks of the transported-velocity solvers on the paper's six SO(3) cases, and of the cost
// of a sweep and of a whole solve as N grows to 10^6 (time linear in N, memory O(N), measured
// as the process's peak resident set). Counters report forward sweeps.
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

#include "cartan/methods/lie_group/continuation.hpp"
#include "cartan/methods/lie_group/multiple_shooting.hpp"
#include "cartan/methods/lie_group/two_level.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace {

using cartan::testing::paper_free_body;
using cartan::testing::paper_oscillator;

void report(benchmark::State& state, const auto& solution) {
  if (!solution.converged()) state.SkipWithError(solution.message.c_str());
  state.counters["sweeps"] = solution.sweeps;
  state.counters["terminal_error"] = solution.terminal_error;
}

// The paper's two-level scheme (finite-difference LM inner loop, Picard outer loop).
void BM_FreeBody_TwoLevel(benchmark::State& state) {
  const auto p = paper_free_body(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::transported::solve_two_level(p, {.tolerance = 1e-8});
    report(state, s);
  }
}
// Augmented shooting with the analytic (tangent-linear) Jacobian.
void BM_FreeBody_Shooting(benchmark::State& state) {
  const auto p = paper_free_body(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::transported::solve_shooting(p, {.tolerance = 1e-8});
    report(state, s);
  }
}
void BM_FreeBody_ShootingOrder2(benchmark::State& state) {
  const auto p = paper_free_body(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::transported::solve_shooting(p, {.order = cartan::transported::SchemeOrder::Second, .tolerance = 1e-8});
    report(state, s);
  }
}
// Multiple shooting (lifted LM over the default ~100-step segments) from the same guess.
void BM_FreeBody_MultipleShooting(benchmark::State& state) {
  const auto p = paper_free_body(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::transported::solve_multiple_shooting(p, {.tolerance = 1e-8});
    report(state, s);
  }
}
// The oscillator at T = 12: the default path (continuation in T from T = 3).
void BM_Oscillator_Continuation(benchmark::State& state) {
  const auto p = paper_oscillator(static_cast<double>(state.range(0)) / 2);
  for (auto _ : state) {
    const auto s = cartan::transported::solve_continuation_in_T(p, {.shooting = {.tolerance = 1e-6}});
    report(state, s);
  }
}

// One forward sweep with the tangent-linear map (6 directions), N = 10^3 .. 10^6 on the paper's
// oscillator at T = 12 (the sweep must stay finite: the benchmark fails if it does not).
void BM_TangentSweep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto p = paper_oscillator(0.5, n);  // T = 12 fixed: h = 12 / N
  const cartan::transported::TransportedScheme<cartan::groups::SO3, cartan::mechanics::SO3Oscillator> scheme(p, cartan::transported::SchemeOrder::First);
  for (auto _ : state) {
    cartan::transported::SweepOutput<cartan::groups::SO3, cartan::mechanics::SO3Oscillator> out;
    if (!cartan::transported::forward_sweep(scheme, Eigen::Vector3d(-1.4, 0.1, 0.1), Eigen::Vector3d::Zero(), nullptr, 6, out)) {
      state.SkipWithError(out.failure.c_str());
    }
  }
  state.SetComplexityN(n);
}

/// A line "Key:   123 kB" of /proc/self/status, in MiB (Linux); 0 where it cannot be read.
double proc_status_mib(const std::string& key) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) / 1024.0;
  }
  return 0;
}

/// Measures the peak memory of one run: resets the process's resident high-water mark
/// (Linux: "5" to /proc/self/clear_refs) and remembers the resident set before the run;
/// `extra_mib()` is then the run's peak above that baseline.
class PeakMemory {
 public:
  PeakMemory() : baseline_(proc_status_mib("VmRSS")) { std::ofstream("/proc/self/clear_refs") << "5"; }
  double extra_mib() const { return proc_status_mib("VmHWM") - baseline_; }

 private:
  double baseline_;
};

// A whole solve (augmented shooting, analytic Jacobian) of the paper's free body at T = 50 with
// N = 10^3 .. 10^6 steps: the iteration count does not grow with N, so the time is linear in N;
// the stored trajectory makes the memory O(N).
void BM_FreeBodySolveScaling(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto p = paper_free_body(0.5, n);
  for (auto _ : state) {
    const PeakMemory memory;
    const auto s = cartan::transported::solve_shooting(p, {.tolerance = 1e-8});
    report(state, s);
    state.counters["peak_MiB"] = memory.extra_mib();
  }
  state.SetComplexityN(n);
}

// A recorded sweep (every node stored: memory O(N)).
void BM_RecordedSweep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto p = paper_oscillator(0.5, n);  // T = 12 fixed: h = 12 / N
  const cartan::transported::TransportedScheme<cartan::groups::SO3, cartan::mechanics::SO3Oscillator> scheme(p, cartan::transported::SchemeOrder::First);
  for (auto _ : state) {
    const PeakMemory memory;
    cartan::transported::TransportedTrajectory<cartan::groups::SO3> trajectory;
    cartan::transported::SweepOutput<cartan::groups::SO3, cartan::mechanics::SO3Oscillator> out;
    out.trajectory = &trajectory;
    if (!cartan::transported::forward_sweep(scheme, Eigen::Vector3d(-1.4, 0.1, 0.1), Eigen::Vector3d::Zero(), nullptr, 0, out)) {
      state.SkipWithError(out.failure.c_str());
    }
    state.counters["peak_MiB"] = memory.extra_mib();
  }
  state.SetComplexityN(n);
}

}  // namespace

// range(0) = 2 lambda: 0, 1, 2 -> lambda = 0, 1/2, 1.
BENCHMARK(BM_FreeBody_TwoLevel)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeBody_Shooting)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeBody_ShootingOrder2)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeBody_MultipleShooting)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Oscillator_Continuation)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TangentSweep)->RangeMultiplier(10)->Range(1000, 1000000)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RecordedSweep)->RangeMultiplier(10)->Range(1000, 1000000)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FreeBodySolveScaling)->RangeMultiplier(10)->Range(1000, 1000000)->Iterations(1)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
