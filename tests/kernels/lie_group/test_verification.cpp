// Independent checks of the transported-velocity solutions (issue: "Verification"): action
// stationarity, energy conservation at the scheme's order, the classical limits lambda = 0
// and 1, the inversion/reflection symmetry, and the six paper cases.
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "cartan/kernels/lie_group/action.hpp"
#include "cartan/methods/lie_group/continuation.hpp"
#include "cartan/methods/lie_group/solve.hpp"
#include "cartan/methods/lie_group/two_level.hpp"
#include "test_support.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace cartan::testing {
namespace {

/// Observed order log2(e(N) / e(2N)).
double observed_order(double coarse, double fine) { return std::log2(coarse / fine); }

template <mechanics::ReducedLagrangian<groups::SO3> L>
transported::TransportedSolution<groups::SO3> solve_or_fail(const transported::TransportedProblem<groups::SO3, L>& p, transported::SchemeOrder order) {
  auto s = transported::solve_continuation_in_T(p, {.shooting = {.order = order, .tolerance = 1e-12}});
  EXPECT_TRUE(s.converged()) << s.message;
  return s;
}

// Endpoint-fixed variation w(t) = sin(pi t/T) a + sin(2 pi t/T) b at the nodes.
std::vector<Eigen::Vector3d> variation(int N) {
  std::vector<Eigen::Vector3d> w(static_cast<std::size_t>(N) + 1);
  for (int k = 0; k <= N; ++k) {
    const double s = static_cast<double>(k) / N;
    w[static_cast<std::size_t>(k)] =
        std::sin(M_PI * s) * Eigen::Vector3d(0.3, -0.2, 0.5) + std::sin(2 * M_PI * s) * Eigen::Vector3d(0.1, 0.4, -0.3);
  }
  return w;
}

// The action's derivative along endpoint-fixed variations at the discrete solution falls as
// O(h) for the paper's scheme and O(h^2) for ours, for every lambda, free body and oscillator
// (docs/paper-notes.md#erratum-1: with the paper's force sign it would not fall at all). Observed
// orders must be within 0.25 of the scheme's order on N = 200 -> 400 -> 800.
TEST(TransportedVerification, ActionIsStationaryAtTheSchemesOrder) {
  for (transported::SchemeOrder order : {transported::SchemeOrder::First, transported::SchemeOrder::Second}) {
    for (double lambda : {0.0, 0.5, 1.0}) {
      std::vector<double> free_body, oscillator;
      for (int N : {200, 400, 800}) {
        const auto fb = paper_free_body(lambda, N, 5.0);
        const auto fs = solve_or_fail(fb, order);
        free_body.push_back(std::abs(
            transported::transported_action_derivative<groups::SO3>(fb.lagrangian, lambda, fb.T, fs.trajectory.g, variation(N))));
        const auto os = paper_oscillator(lambda, N, 3.0);
        const auto oss = solve_or_fail(os, order);
        oscillator.push_back(std::abs(
            transported::transported_action_derivative<groups::SO3>(os.lagrangian, lambda, os.T, oss.trajectory.g, variation(N))));
      }
      const double expected = static_cast<double>(order);
      for (const auto* d : {&free_body, &oscillator}) {
        EXPECT_NEAR(observed_order((*d)[0], (*d)[1]), expected, 0.25)
            << "lambda " << lambda << " order " << expected << " dS: " << (*d)[0] << " " << (*d)[1] << " " << (*d)[2];
        EXPECT_NEAR(observed_order((*d)[1], (*d)[2]), expected, 0.25)
            << "lambda " << lambda << " order " << expected << " dS: " << (*d)[0] << " " << (*d)[1] << " " << (*d)[2];
      }
    }
  }
}

// Along solutions d/dt(1/2 v.Iv) = v . eta, so the free body's 1/2 v.Iv is conserved for every
// lambda and the oscillator's 1/2 v.Iv + V(g); the discrete drift shrinks at least at the
// scheme's order. `expected[o - 1]` is the order measured for scheme order o (within 0.25).
template <class MakeProblem, class Energy>
void expect_energy_drift_at_order(const MakeProblem& make, const Energy& energy, const std::string& what,
                                  const std::array<double, 2>& expected) {
  for (transported::SchemeOrder order : {transported::SchemeOrder::First, transported::SchemeOrder::Second}) {
    const double expected_order = expected[static_cast<std::size_t>(order) - 1];
    for (double lambda : {0.0, 0.5, 1.0}) {
      std::vector<double> drift;
      for (int N : {200, 400, 800}) {
        const auto s = solve_or_fail(make(lambda, N), order);
        const auto& tr = s.trajectory;
        double worst = 0;
        for (std::size_t k = 0; k < tr.g.size(); ++k) {
          worst = std::max(worst, std::abs(energy(tr.g[k], tr.v[k]) - energy(tr.g[0], tr.v[0])));
        }
        drift.push_back(worst);
      }
      const std::string context = what + " order " + std::to_string(static_cast<int>(order)) + " lambda " +
                                  std::to_string(lambda) + " drift " + std::to_string(drift[0]) + " " +
                                  std::to_string(drift[1]) + " " + std::to_string(drift[2]);
      EXPECT_NEAR(observed_order(drift[0], drift[1]), expected_order, 0.25) << context;
      EXPECT_NEAR(observed_order(drift[1], drift[2]), expected_order, 0.25) << context;
    }
  }
}

TEST(TransportedVerification, EnergyDriftShrinksAtTheSchemesOrder) {
  const Eigen::Matrix3d inertia = paper_inertia();
  expect_energy_drift_at_order([](double lambda, int N) { return paper_oscillator(lambda, N, 3.0); },
                               [&](const groups::SO3::Element& g, const Eigen::Vector3d& v) {
                                 return 0.5 * v.dot(inertia * v) + mechanics::SO3TracePotential().value(g);
                               },
                               "oscillator T = 3", {1, 2});
  // Measured: the order-2 scheme conserves the free body's kinetic energy to O(h^3) (3.00 for
  // every lambda on N = 200 -> 400 -> 800), one order better than its global error.
  expect_energy_drift_at_order([](double lambda, int N) { return paper_free_body(lambda, N, 10.0); },
                               [&](const groups::SO3::Element&, const Eigen::Vector3d& v) { return 0.5 * v.dot(inertia * v); },
                               "free body T = 10", {1, 3});
}

// lambda = 0: v solves the classical Euler equation I v' + v x I v = 0; lambda = 1: the right
// Euler–Poincaré equation I v' - v x I v = 0. Reference: classical RK4 (an independent
// integrator) from the v0 the solver found, with 64 substeps per step (error ~1e-12). The
// difference falls at the scheme's order.
TEST(TransportedVerification, ClassicalLimitsLambdaZeroAndOne) {
  const Eigen::Matrix3d inertia = paper_inertia(), inverse = inertia.inverse();
  for (double lambda : {0.0, 1.0}) {
    const double sign = lambda == 0 ? -1 : 1;
    auto rhs = [&](const Eigen::Vector3d& v) -> Eigen::Vector3d {
      return inverse * (sign * v.cross(inertia * v));
    };
    for (transported::SchemeOrder order : {transported::SchemeOrder::First, transported::SchemeOrder::Second}) {
      std::vector<double> error;
      for (int N : {250, 500, 1000}) {
        const auto s = solve_or_fail(paper_free_body(lambda, N, 50.0), order);
        Eigen::Vector3d v = s.v0;
        const int sub = 64;
        const double dt = 50.0 / N / sub;
        double worst = 0;
        for (int k = 0; k < N; ++k) {
          for (int j = 0; j < sub; ++j) {
            const Eigen::Vector3d k1 = rhs(v), k2 = rhs(v + dt / 2 * k1), k3 = rhs(v + dt / 2 * k2),
                                  k4 = rhs(v + dt * k3);
            v += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
          }
          worst = std::max(worst, (v - s.trajectory.v[static_cast<std::size_t>(k) + 1]).norm());
        }
        error.push_back(worst);
      }
      EXPECT_NEAR(observed_order(error[1], error[2]), static_cast<double>(order), 0.25)
          << "lambda " << lambda << " errors " << error[0] << " " << error[1] << " " << error[2];
    }
  }
}

// Inversion g -> g^{-1} maps lambda to 1 - lambda, and the reflection S = diag(-1,1,1) maps the
// paper's free-body gT to gT^{-1} while fixing I: v0(1) = S v0(0) and v0(1/2)_1 = 0. The
// discrete scheme inherits the symmetry, so it holds to rounding of the solves (1e-11).
TEST(TransportedVerification, InversionReflectionSymmetryOfTheFreeBody) {
  const auto s0 = transported::solve_shooting(paper_free_body(0.0), {.tolerance = 1e-13});
  const auto s1 = transported::solve_shooting(paper_free_body(1.0), {.tolerance = 1e-13});
  const auto sh = transported::solve_shooting(paper_free_body(0.5), {.tolerance = 1e-13});
  ASSERT_TRUE(s0.converged() && s1.converged() && sh.converged());
  EXPECT_LE((s1.v0 - Eigen::Vector3d(-1, 1, 1).asDiagonal() * s0.v0).norm(), 1e-11);
  EXPECT_LE(std::abs(sh.v0[0]), 1e-11);
  // The paper's "mirror images", made precise: phi(g) = S g^{-1} S maps the lambda = 0 solution
  // to the lambda = 1 one, so g_1(t_k) = S g_0(t_k)^T S at every node (and on the sphere
  // a_1(t) = S g_0(t)^T S a0). Rounding of two solves over N = 1000 steps: 1e-10.
  const Eigen::Matrix3d reflect = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  double worst = 0;
  for (std::size_t k = 0; k < s0.trajectory.g.size(); ++k) {
    worst = std::max(worst, max_abs_diff(s1.trajectory.g[k], reflect * s0.trajectory.g[k].transpose() * reflect));
  }
  EXPECT_LE(worst, 1e-10);
}

// Convergence to the continuous solution against a fine reference (order 2, N = 6400; its error
// ~(h/16)^2 is far below the coarse errors): the discrete v0 and g(T/2) converge at order 1 for
// the paper's scheme and order 2 for ours (within 0.25 on N = 200 -> 400 -> 800), lambda = 1/2.
TEST(TransportedVerification, ConvergenceOrderAgainstFineReference) {
  const auto reference = solve_or_fail(paper_oscillator(0.5, 6400, 3.0), transported::SchemeOrder::Second);
  const Eigen::Matrix3d g_mid = reference.trajectory.g[3200];
  for (transported::SchemeOrder order : {transported::SchemeOrder::First, transported::SchemeOrder::Second}) {
    std::vector<double> error;
    for (int N : {200, 400, 800}) {
      const auto s = solve_or_fail(paper_oscillator(0.5, N, 3.0), order);
      const Eigen::Vector3d dg = groups::SO3::log(g_mid.transpose() * s.trajectory.g[static_cast<std::size_t>(N / 2)]);
      error.push_back(std::max((s.v0 - reference.v0).norm(), dg.norm()));
    }
    const double expected = static_cast<double>(order);
    EXPECT_NEAR(observed_order(error[0], error[1]), expected, 0.25) << error[0] << " " << error[1] << " " << error[2];
    EXPECT_NEAR(observed_order(error[1], error[2]), expected, 0.25) << error[0] << " " << error[1] << " " << error[2];
  }
}

// The paper's six cases with the default path (direct shooting when it converges quickly,
// continuation in T otherwise): all converge with terminal error below the paper's tolerance.
TEST(TransportedVerification, SixPaperCasesConverge) {
  for (double lambda : {0.0, 0.5, 1.0}) {
    const auto fb = transported::solve_continuation_in_T(paper_free_body(lambda), {.shooting = {.tolerance = 1e-10}});
    EXPECT_TRUE(fb.converged()) << fb.message;
    EXPECT_LT(fb.terminal_error, 1e-8);
    EXPECT_EQ(fb.branch, "direct from the geodesic guess");
    const auto os = transported::solve_continuation_in_T(paper_oscillator(lambda), {.shooting = {.tolerance = 1e-10}});
    EXPECT_TRUE(os.converged()) << os.message;
    EXPECT_LT(os.terminal_error, 1e-6);
    EXPECT_EQ(os.branch.rfind("continued in T from T = 3", 0), 0u) << os.branch;
  }
}

// A failed direct attempt handed to continuation in T (the default strategy's first step) is
// not repeated: the path is the same computation from T/2 on, so the result is bitwise the same
// and costs exactly the direct attempt's sweeps less.
TEST(TransportedVerification, ContinuationInTReusesAFailedDirectAttempt) {
  const transported::ContinuationOptions options{.shooting = {.tolerance = 1e-10}};
  const auto problem = paper_oscillator(0.5);
  transported::ShootingOptions direct_options = options.shooting;
  direct_options.no_progress_window = options.no_progress_window;
  const auto direct = transported::solve_shooting(problem, direct_options);
  ASSERT_FALSE(direct.converged()) << "the T = 12 oscillator no longer needs continuation: pick a harder case";
  const auto full = transported::solve_continuation_in_T(problem, options);
  const auto reused = transported::solve_continuation_in_T(problem, options, std::nullopt, std::nullopt, &direct);
  ASSERT_TRUE(full.converged() && reused.converged()) << full.message << reused.message;
  EXPECT_EQ(reused.v0, full.v0);
  EXPECT_EQ(reused.branch, full.branch);
  EXPECT_EQ(reused.sweeps, full.sweeps - direct.sweeps);
  EXPECT_THROW(transported::solve_continuation_in_T(problem, options, std::nullopt, std::nullopt, &full),
               std::invalid_argument);
}

// Continuation in lambda from the classical lambda = 0 solution (itself continued in T at
// T = 12) reaches the same branch as continuation in T at the target lambda. Measured: v0
// agrees to 1e-15 (free body) and about 1e-9 (oscillator, T = 12) for lambda = 1/2 and 1. Both
// solves stop at |r| <= 1e-8 and distinct branches differ by O(0.1) in v0, so 1e-6 separates
// "same branch" from "another branch" with room for the Jacobian's conditioning at T = 12.
TEST(TransportedVerification, ContinuationInLambdaReachesTheContinuationInTBranch) {
  const transported::ContinuationOptions options{.shooting = {.tolerance = 1e-8}};
  for (double lambda : {0.5, 1.0}) {
    const auto fb = transported::solve_continuation_in_lambda(paper_free_body(lambda), 0.0, options);
    ASSERT_TRUE(fb.converged()) << fb.message;
    EXPECT_EQ(fb.branch.rfind("continued in lambda from lambda = 0 [direct from the geodesic guess]", 0), 0u) << fb.branch;
    EXPECT_LE((fb.v0 - transported::solve_shooting(paper_free_body(lambda), options.shooting).v0).norm(), 1e-7);
    const auto os = transported::solve_continuation_in_lambda(paper_oscillator(lambda), 0.0, options);
    ASSERT_TRUE(os.converged()) << os.message;
    EXPECT_LT(os.terminal_error, 1e-8);
    EXPECT_EQ(os.branch.rfind("continued in lambda from lambda = 0 [continued in T from T = 3", 0), 0u) << os.branch;
    EXPECT_LE((os.v0 - transported::solve_continuation_in_T(paper_oscillator(lambda), options).v0).norm(), 1e-6) << lambda;
  }
}

// Continuation in T follows one branch: the default path (first increment 1/8 of the way,
// growing 1.5x) ends where a path 16 times finer does. A corrector that converges far from the
// predictor has jumped branches and is rejected (max_correction): without that check the coarse
// path jumped, at lambda = 0 and 1/2, to a branch turning 1.5 revolutions (action about -6.4)
// while the fine path stays on the one turning 0.6 revolutions (action about -18.1).
// Both solves stop at |r| <= 1e-8 and the branches differ by O(0.1) in v0, so 1e-6 in v0 says
// "same branch" with room for the Jacobian's conditioning near T = 12.
TEST(TransportedVerification, ContinuationInTDoesNotJumpBranches) {
  transported::ContinuationOptions coarse{.shooting = {.tolerance = 1e-8}};
  transported::ContinuationOptions fine = coarse;
  fine.initial_stages = 128;
  for (double lambda : {0.0, 0.5, 1.0}) {
    const auto a = transported::solve_continuation_in_T(paper_oscillator(lambda), coarse);
    const auto b = transported::solve_continuation_in_T(paper_oscillator(lambda), fine);
    ASSERT_TRUE(a.converged() && b.converged()) << a.message << b.message;
    EXPECT_LE((a.v0 - b.v0).norm(), 1e-6) << lambda;
    double turned = 0;  // total rotation angle along the path, in revolutions
    for (std::size_t k = 0; k + 1 < a.trajectory.g.size(); ++k) {
      turned += groups::SO3::log(a.trajectory.g[k].transpose() * a.trajectory.g[k + 1]).norm() / (2 * std::numbers::pi);
    }
    EXPECT_LT(turned, 1.0) << lambda;
    // The branch's action (docs/paper-notes.md, erratum 4): S_h = -18.146, -18.114, -18.148 at
    // lambda = 0, 1/2, 1 (N = 800; 3e-5 from N = 1600); the 1.5-revolution branch has about -6.4,
    // so 0.1 tells the branches apart with room for lambda's 0.03.
    const auto p = paper_oscillator(lambda);
    EXPECT_NEAR(transported::transported_action<groups::SO3>(p.lagrangian, lambda, a.trajectory.t, a.trajectory.g), -18.1,
                0.1)
        << lambda;
  }
}

// The discrete action's inputs are checked (it used to read out of bounds on short inputs).
TEST(TransportedVerification, ActionRejectsBadInput) {
  const mechanics::RigidBody body(paper_inertia());
  const std::vector<groups::SO3::Element> one{groups::SO3::identity()}, two{groups::SO3::identity(), groups::SO3::identity()};
  expect_invalid([&] { transported::transported_action<groups::SO3>(body, 0.5, 1.0, one); }, "g.size() = 1");
  expect_invalid([&] { transported::transported_action<groups::SO3>(body, 0.5, -1.0, two); }, "T = -1");
  expect_invalid([&] { transported::transported_action<groups::SO3>(body, std::nan(""), 1.0, two); }, "lambda");
  const std::vector<Eigen::Vector3d> w_short{Eigen::Vector3d::Zero()};
  expect_invalid([&] { transported::transported_action_derivative<groups::SO3>(body, 0.5, 1.0, two, w_short); }, "w.size() = 1");
}

// A result stopped on request keeps the best iterate's samples but no action (solve.hpp: over a
// long trajectory the action costs about two sweeps, the work a stop is there to save); the same
// solve left to run has one. Stopped here by the monitor's stop callback after two iterations of
// shooting on the paper's T = 12 oscillator (it needs more: measured 5 from the geodesic guess), so
// nothing depends on the clock.
TEST(TransportedVerification, AStoppedResultHasItsIterateButNoAction) {
  const auto problem = paper_oscillator(0.5, 400);
  transported::SolveOptions options;
  options.method = transported::Method::Shooting;
  int iterations = 0;
  options.monitor = SolveMonitor([&](const Progress&) { ++iterations; }, [&] { return iterations >= 2; });
  const auto stopped = transported::solve(problem, options);
  EXPECT_EQ(stopped.status, Status::Interrupted) << stopped.message;
  EXPECT_EQ(stopped.trajectory.t.size(), 401u);
  EXPECT_TRUE(std::isnan(stopped.action));
  options.monitor = SolveMonitor();
  const auto finished = transported::solve(problem, options);
  EXPECT_FALSE(stopped_on_request(finished.status)) << finished.message;
  EXPECT_TRUE(std::isfinite(finished.action)) << finished.message;
}

}  // namespace
}  // namespace cartan::testing
