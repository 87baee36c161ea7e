// What a step and a whole solve cost, as ratios measured side by side in one process (thread CPU
// time, CLOCK_THREAD_CPUTIME_ID; the median of the rounds), so that the figures survive the
// load of a shared machine (bench/README.md, "Scheme and solve costs"):
//  * BM_StepCost/<case>: one primal sweep of cartan's scheme, the same sweep written naively
//    (reference_step.hpp; SO(3) only, checked to reach the same state), and the tangent-linear
//    sweep with 2n directions (v0 and xi0), interleaved round by round. Counters: ns per step of
//    each, primal/reference and tangent/primal.
//  * BM_SolveCost/<case>/<2 lambda>: the library's default solve (`transported::solve`, method
//    auto) against one primal sweep of the same problem, interleaved; the counter
//    `sweep_equivalents` is the solve's time in primal sweeps of the same N.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <type_traits>
#include <vector>

#include "cartan/mechanics/free_body.hpp"
#include "cartan/methods/lie_group/solve.hpp"
#include "reference_step.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace {

using namespace cartan;

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

template <class F>
double timed(F&& f) {
  const double start = thread_cpu_seconds();
  f();
  return thread_cpu_seconds() - start;
}

double median(std::vector<double> x) {
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2), x.end());
  return x[x.size() / 2];
}

template <class G, class L>
bool sweep(const transported::TransportedScheme<G, L>& scheme, const groups::TangentOf<G>& v0, int columns,
           transported::SweepOutput<G, L>& out) {
  return transported::forward_sweep(scheme, v0, groups::CovectorOf<G>::Zero(), nullptr, columns, out);
}

/// Times primal and tangent sweeps (and, when `reference` is callable, the naive reference) of
/// `problem` round by round; reports ns per step and the ratios.
template <class G, class L, class Reference>
void step_cost(benchmark::State& state, const transported::TransportedProblem<G, L>& problem,
               const groups::TangentOf<G>& v0, Reference reference) {
  constexpr int n = G::kDim;
  const transported::TransportedScheme<G, L> scheme(problem, transported::SchemeOrder::First);
  std::vector<double> primal, tangent, naive;
  for (auto _ : state) {
    transported::SweepOutput<G, L> out;
    primal.push_back(timed([&] {
      if (!sweep(scheme, v0, 0, out)) state.SkipWithError(out.failure.c_str());
    }));
    benchmark::DoNotOptimize(out.last);
    transported::SweepOutput<G, L> dout;
    tangent.push_back(timed([&] {
      if (!sweep(scheme, v0, 2 * n, dout)) state.SkipWithError(dout.failure.c_str());
    }));
    benchmark::DoNotOptimize(dout.last);
    if constexpr (std::is_invocable_v<Reference>) {
      bench::ReferenceState r;
      naive.push_back(timed([&] { r = reference(); }));
      benchmark::DoNotOptimize(r);
      // The reference must compute the same scheme: same final point to rounding.
      if ((r.g - out.last.g).norm() > 1e-9 || (r.mu - out.last.mu).norm() > 1e-9 * (1 + r.mu.norm())) {
        state.SkipWithError("the naive reference and cartan's sweep disagree");
      }
    }
  }
  const double per_step = 1e9 / problem.N;
  state.counters["primal_ns"] = median(primal) * per_step;
  state.counters["tangent_ns"] = median(tangent) * per_step;
  state.counters["tangent/primal"] = median(tangent) / median(primal);
  if (!naive.empty()) {
    state.counters["reference_ns"] = median(naive) * per_step;
    state.counters["primal/reference"] = median(primal) / median(naive);
  }
}

const Eigen::Vector3d kSO3V0(-0.28, 0.02, 0.02);

void BM_StepCost_SO3FreeBody(benchmark::State& state) {
  const auto p = testing::paper_free_body(0.5);
  step_cost(state, p, kSO3V0, [&] {
    return bench::reference_sweep(testing::paper_inertia(), false, p.lambda, p.step(), p.N, kSO3V0);
  });
}
void BM_StepCost_SO3Oscillator(benchmark::State& state) {
  const auto p = testing::paper_oscillator(0.5);
  step_cost(state, p, kSO3V0, [&] {
    return bench::reference_sweep(testing::paper_inertia(), true, p.lambda, p.step(), p.N, kSO3V0);
  });
}
void BM_StepCost_H3Oscillator(benchmark::State& state) {
  const transported::TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator> p{
      mechanics::h3_oscillator(), 0.5, 2.0, 1000, groups::Heisenberg::identity(), Eigen::Vector3d(1, 0.5, 0.8)};
  step_cost(state, p, Eigen::Vector3d(0.5, 0.25, 0.4), 0);
}
void BM_StepCost_SE2FreeBody(benchmark::State& state) {
  const transported::TransportedProblem<groups::SE2, mechanics::SE2FreeBody> p{
      mechanics::SE2FreeBody(Eigen::Vector3d(2, 1, 3).asDiagonal()), 0.5, 2.0, 1000, groups::SE2::identity(),
      groups::SE2::exp(Eigen::Vector3d(0.7, 1.0, -0.4))};
  step_cost(state, p, Eigen::Vector3d(0.35, 0.5, -0.2), 0);
}
void BM_StepCost_SE3FreeBody(benchmark::State& state) {
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  const Vector6d x = (Vector6d() << 0.3, -0.2, 0.5, 1.0, 0.4, -0.6).finished();
  const transported::TransportedProblem<groups::SE3, mechanics::SE3FreeBody> p{
      mechanics::SE3FreeBody(Vector6d(1, 2, 3, 4, 4, 4).asDiagonal()), 0.5, 2.0, 1000, groups::SE3::identity(),
      groups::SE3::exp(x)};
  step_cost(state, p, Vector6d(x / 2), 0);
}

/// The default solve against one primal sweep of the same problem, interleaved.
template <class G, class L>
void solve_cost(benchmark::State& state, const transported::TransportedProblem<G, L>& problem, double tol) {
  const transported::TransportedScheme<G, L> scheme(problem, transported::SchemeOrder::First);
  const groups::TangentOf<G> v0 = transported::geodesic_guess(problem);
  std::vector<double> solve_time, sweep_time;
  transported::TransportedSolution<G> s;
  transported::SolveOptions options;
  options.tol = tol;
  for (auto _ : state) {
    solve_time.push_back(timed([&] { s = transported::solve(problem, options); }));
    transported::SweepOutput<G, L> out;
    sweep_time.push_back(timed([&] { sweep(scheme, v0, 0, out); }));
    benchmark::DoNotOptimize(out.last);
  }
  if (!s.converged()) state.SkipWithError(s.message.c_str());
  state.counters["sweeps"] = s.sweeps;
  state.counters["solve_ms"] = median(solve_time) * 1e3;
  state.counters["sweep_equivalents"] = median(solve_time) / median(sweep_time);
}

// range(0) = 2 lambda. The paper's cases with the tolerances of bench_transported.
void BM_SolveCost_FreeBody(benchmark::State& state) {
  solve_cost(state, testing::paper_free_body(static_cast<double>(state.range(0)) / 2), 1e-8);
}
void BM_SolveCost_Oscillator(benchmark::State& state) {
  solve_cost(state, testing::paper_oscillator(static_cast<double>(state.range(0)) / 2), 1e-6);
}

}  // namespace

BENCHMARK(BM_StepCost_SO3FreeBody)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepCost_SO3Oscillator)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepCost_H3Oscillator)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepCost_SE2FreeBody)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepCost_SE3FreeBody)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SolveCost_FreeBody)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SolveCost_Oscillator)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
