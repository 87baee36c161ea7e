// Times the collocation solver on the paper's H3 oscillator BVP (appendix sec-app-H3), in process,
// in CPU time: the C++ side of bench/compare_collocation_warm.py, which times SciPy's solve_bvp
// in its own process on the same problems and alternates the two sides case by case.
//
// Serve mode (default): one request a line on standard input,
//   a b c lambda T nodes tol repeats samples
// (gT = (a, b, c), g0 = e, unit inertia, the geodesic guess on `nodes` uniform nodes), answered by
// one JSON line: the CPU time (CLOCK_PROCESS_CPUTIME_ID; the process has one thread) of each of
// `repeats` solves after one untimed warm-up solve ("cpu_s"), the warm-up's own CPU and wall time
// ("first_cpu_s", "first_wall_s"), status, final mesh size, Newton iterations, Jacobians, and the
// solution (a, b, c, v) at `samples` uniform times ("y", row-major samples x 6) so that the
// caller can check that both sides found the same solution. An empty line or end of input ends.
//
// --once a b c lambda T [repeats]: the cold/warm comparison in a fresh process (bench/README.md,
// "Cold and warm"): the wall and CPU time of the process's first solve, then the median of
// `repeats` (default 50) more solves of the same problem, and the page faults (getrusage) taken
// during the first solve and during all the others.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cartan/kernels/lie_group/heisenberg_collocation.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"

namespace {

using Problem = cartan::transported::TransportedProblem<cartan::groups::Heisenberg, cartan::mechanics::H3Oscillator>;

double clock_seconds(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt + usage.ru_majflt;
}

struct Case {
  double a = 0, b = 0, c = 0, lambda = 0, T = 1, tol = 1e-8;
  int nodes = 11, repeats = 10, samples = 11;
};

Problem problem_of(const Case& c) {
  return Problem{cartan::mechanics::h3_oscillator(), c.lambda, c.T, c.nodes - 1, cartan::groups::Heisenberg::identity(),
                 Eigen::Vector3d(c.a, c.b, c.c)};
}

cartan::numerics::BvpResult solve(const Problem& problem, double tol) {
  return cartan::transported::solve_heisenberg_collocation(problem, {.tol = tol, .max_nodes = 100000});
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

void serve() {
  std::string line;
  std::cout.precision(17);
  while (std::getline(std::cin, line) && !line.empty()) {
    std::istringstream in(line);
    Case c;
    in >> c.a >> c.b >> c.c >> c.lambda >> c.T >> c.nodes >> c.tol >> c.repeats >> c.samples;
    if (!in) {
      std::cout << R"({"error": "bad request"})" << std::endl;
      continue;
    }
    const Problem problem = problem_of(c);
    const double wall0 = clock_seconds(CLOCK_MONOTONIC), cpu0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    cartan::numerics::BvpResult r = solve(problem, c.tol);
    const double first_cpu = clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    const double first_wall = clock_seconds(CLOCK_MONOTONIC) - wall0;
    std::vector<double> cpu;
    for (int i = 0; i < c.repeats; ++i) {
      const double start = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
      r = solve(problem, c.tol);
      cpu.push_back(clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - start);
    }
    std::cout << R"({"status": ")" << cartan::to_string(r.status) << R"(", "nodes": )" << r.t.size()
              << R"(, "newton": )" << r.newton_iterations << R"(, "jacobians": )" << r.jacobian_evaluations
              << R"(, "first_cpu_s": )" << first_cpu << R"(, "first_wall_s": )" << first_wall << R"(, "cpu_s": [)";
    for (std::size_t i = 0; i < cpu.size(); ++i) std::cout << (i ? ", " : "") << cpu[i];
    std::cout << R"(], "y": [)";
    if (r.success() && c.samples >= 2) {
      const cartan::numerics::CubicHermite s = r.interpolant();
      Eigen::VectorXd y(r.y.rows());
      for (int j = 0; j < c.samples; ++j) {
        s.evaluate(c.T * j / (c.samples - 1), &y, nullptr);
        for (Eigen::Index i = 0; i < y.size(); ++i) std::cout << (j + i ? ", " : "") << y[i];
      }
    }
    std::cout << "]}" << std::endl;
  }
}

int once(int argc, char** argv) {
  if (argc < 7) {
    std::cerr << "usage: collocation_timer --once a b c lambda T [repeats]\n";
    return 2;
  }
  Case c;
  c.a = std::atof(argv[2]);
  c.b = std::atof(argv[3]);
  c.c = std::atof(argv[4]);
  c.lambda = std::atof(argv[5]);
  c.T = std::atof(argv[6]);
  const int repeats = argc > 7 ? std::atoi(argv[7]) : 50;
  const Problem problem = problem_of(c);
  const long faults0 = minor_faults();
  const double wall0 = clock_seconds(CLOCK_MONOTONIC), cpu0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
  cartan::numerics::BvpResult r = solve(problem, c.tol);
  const double first_cpu = clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
  const double first_wall = clock_seconds(CLOCK_MONOTONIC) - wall0;
  const long faults1 = minor_faults();
  std::vector<double> cpu, wall;
  for (int i = 0; i < repeats; ++i) {
    const double w = clock_seconds(CLOCK_MONOTONIC), start = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    r = solve(problem, c.tol);
    cpu.push_back(clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - start);
    wall.push_back(clock_seconds(CLOCK_MONOTONIC) - w);
  }
  const long faults2 = minor_faults();
  std::printf(
      "{\"status\": \"%s\", \"nodes\": %ld, \"first_cpu_s\": %.9f, \"first_wall_s\": %.9f, \"warm_cpu_s\": %.9f, "
      "\"warm_wall_s\": %.9f, \"first_page_faults\": %ld, \"warm_page_faults\": %ld, \"repeats\": %d}\n",
      std::string(cartan::to_string(r.status)).c_str(), static_cast<long>(r.t.size()), first_cpu, first_wall,
      median(cpu), median(wall), faults1 - faults0, faults2 - faults1, repeats);
  return r.success() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--once") return once(argc, argv);
  serve();
  return 0;
}
