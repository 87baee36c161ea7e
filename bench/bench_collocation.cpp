// The collocation solver on the paper's H3 oscillator BVP (appendix sec-app-H3) at tol 1e-8,
// from the geodesic guess on 11 nodes, for the endpoints and lambdas of
// bench/compare_collocation.py (which compares with SciPy's solve_bvp). In-process, warm: the
// time of a solve without process start-up. Counters: final mesh size, Newton iterations and
// Jacobians. The third argument: 1 reuses the Newton matrix (chord steps, the default), 0 not.
#include <benchmark/benchmark.h>

#include <array>

#include "cartan/kernels/lie_group/heisenberg_collocation.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"

namespace {

constexpr std::array<std::array<double, 3>, 3> kEndpoints{{{1, 0.5, 0.8}, {-1, 1, 0.5}, {0.5, -1, -1}}};

void BM_H3Collocation(benchmark::State& state) {
  const auto& gT = kEndpoints[static_cast<std::size_t>(state.range(0))];
  const double lambda = static_cast<double>(state.range(1)) / 2;
  const bool reuse = state.range(2) != 0;
  const cartan::transported::TransportedProblem<cartan::groups::Heisenberg, cartan::mechanics::H3Oscillator> problem{
      cartan::mechanics::h3_oscillator(), lambda, 1.0, 10, cartan::groups::Heisenberg::identity(), Eigen::Vector3d(gT[0], gT[1], gT[2])};
  cartan::numerics::BvpResult r;
  for (auto _ : state) {
    r = cartan::transported::solve_heisenberg_collocation(problem, {.tol = 1e-8, .reuse_jacobian = reuse});
    benchmark::DoNotOptimize(r.y.data());
  }
  if (!r.success()) state.SkipWithError(r.message.c_str());
  state.counters["nodes"] = static_cast<double>(r.t.size());
  state.counters["newton"] = r.newton_iterations;
  state.counters["jacobians"] = r.jacobian_evaluations;
}
BENCHMARK(BM_H3Collocation)->ArgsProduct({{0, 1, 2}, {0, 1, 2}, {0, 1}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
