// Levenberg–Marquardt on systems with known roots, and its failure reports.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include "cartan/numerics/nonlinear_solve.hpp"
#include "test_support.hpp"

namespace cartan::numerics {
namespace {

// Rosenbrock as a square system r = (10(x2 - x1^2), 1 - x1): root (1, 1).
bool rosenbrock(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
  r.resize(2);
  r << 10 * (x[1] - x[0] * x[0]), 1 - x[0];
  if (jac) {
    jac->resize(2, 2);
    *jac << -20 * x[0], 10, -1, 0;
  }
  return true;
}

TEST(LevenbergMarquardt, SolvesRosenbrockWithAnalyticJacobian) {
  const auto report = levenberg_marquardt(rosenbrock, Eigen::Vector2d(-1.2, 1.0), {.tolerance = 1e-13});
  ASSERT_EQ(report.status, Status::Converged) << report.message;
  EXPECT_NEAR(report.x[0], 1.0, 1e-13);  // |r| <= 1e-13 and J is well conditioned at the root
  EXPECT_NEAR(report.x[1], 1.0, 1e-12);
  EXPECT_LE(report.residual_norm, 1e-13);
  EXPECT_EQ(report.residual_history.back(), report.residual_norm);
}

TEST(LevenbergMarquardt, ForwardDifferenceJacobianCountsEvaluations) {
  int calls = 0, with_jacobian = 0;
  auto f = [&calls](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    ++calls;
    return rosenbrock(x, r, nullptr);
  };
  const ResidualFunction fd = with_forward_difference_jacobian(f, 1e-7);
  const ResidualFunction counted = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    with_jacobian += jac != nullptr;
    return fd(x, r, jac);
  };
  const auto report = levenberg_marquardt(counted, Eigen::Vector2d(-1.2, 1.0), {.tolerance = 1e-12});
  ASSERT_EQ(report.status, Status::Converged) << report.message;
  // residual + one per unknown where a Jacobian was asked for, the residual alone elsewhere
  EXPECT_EQ(calls, report.evaluations + 2 * with_jacobian);
  EXPECT_NEAR(report.x[0], 1.0, 1e-11);
}

// max_initial_residual: a start whose |r| exceeds it is abandoned after that one evaluation
// (status NoProgress, the start returned unchanged); a start below it solves as without it.
TEST(LevenbergMarquardt, AbandonsAStartAboveMaxInitialResidual) {
  const Eigen::Vector2d start(-1.2, 1.0);  // |r| = |(-4.4, 2.2)| = 4.92
  const auto abandoned = levenberg_marquardt(rosenbrock, start, {.tolerance = 1e-12, .max_initial_residual = 4.0});
  EXPECT_EQ(abandoned.status, Status::NoProgress) << abandoned.message;
  EXPECT_EQ(abandoned.evaluations, 1);
  EXPECT_EQ(abandoned.x, Eigen::VectorXd(start));
  EXPECT_NE(abandoned.message.find("max_initial_residual"), std::string::npos) << abandoned.message;
  const auto solved = levenberg_marquardt(rosenbrock, start, {.tolerance = 1e-12, .max_initial_residual = 5.0});
  const auto plain = levenberg_marquardt(rosenbrock, start, {.tolerance = 1e-12});
  ASSERT_EQ(solved.status, Status::Converged) << solved.message;
  EXPECT_EQ(solved.x, plain.x);
  testing::expect_invalid([] { levenberg_marquardt(rosenbrock, Eigen::Vector2d(0, 0), {.max_initial_residual = 0.0}); },
                 {"max_initial_residual", "0"});
}

// Where the last step's rate predicts convergence, the trial point is evaluated without its
// Jacobian (a tangent-linear sweep costs several plain ones): on Rosenbrock, whose Newton phase
// converges quadratically, the converged point is such an evaluation; every point that was not
// the last got its Jacobian (the solve continued from it).
TEST(LevenbergMarquardt, AsksNoJacobianWhereItExpectsConvergence) {
  std::vector<bool> asked;
  const ResidualFunction f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    asked.push_back(jac != nullptr);
    return rosenbrock(x, r, jac);
  };
  const auto report = levenberg_marquardt(f, Eigen::Vector2d(-1.2, 1.0), {.tolerance = 1e-12});
  ASSERT_EQ(report.status, Status::Converged) << report.message;
  ASSERT_GE(asked.size(), 3u);
  EXPECT_FALSE(asked.back());
  EXPECT_TRUE(asked.front());
  EXPECT_EQ(static_cast<int>(asked.size()), report.evaluations);
}

TEST(LevenbergMarquardt, ReportsStallAtNonZeroMinimum) {
  // r = (x^2 + 1): no root; minimum |r| = 1 at x = 0.
  auto f = [](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    r = Eigen::VectorXd::Constant(1, x[0] * x[0] + 1);
    if (jac) *jac = Eigen::MatrixXd::Constant(1, 1, 2 * x[0]);
    return true;
  };
  const auto report = levenberg_marquardt(f, Eigen::VectorXd::Constant(1, 3.0), {.max_iterations = 500});
  EXPECT_NE(report.status, Status::Converged);
  EXPECT_NEAR(report.residual_norm, 1.0, 1e-6);
  EXPECT_NE(report.message.find("|r| = "), std::string::npos) << report.message;
}

TEST(LevenbergMarquardt, ReportsNonFiniteAndIterationLimit) {
  auto nan_f = [](const Eigen::VectorXd&, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    r = Eigen::VectorXd::Constant(1, std::nan(""));
    if (jac) *jac = Eigen::MatrixXd::Ones(1, 1);
    return true;
  };
  EXPECT_EQ(levenberg_marquardt(nan_f, Eigen::VectorXd::Zero(1)).status, Status::NonFinite);
  const auto limited = levenberg_marquardt(rosenbrock, Eigen::Vector2d(-1.2, 1.0), {.max_iterations = 1});
  EXPECT_EQ(limited.status, Status::MaxIterations);
  EXPECT_EQ(limited.iterations, 1);
  EXPECT_NE(limited.message.find("max-iterations after 1 iterations"), std::string::npos) << limited.message;
}

// Bad options, a non-finite start and an empty function are errors naming the value.
// A residual evaluation that fails because its monitor's stop is pending (a sweep stopped by the
// time limit or a cancel flag) ends the solve as interrupted, not non-finite: at the start, and
// at an accepted point whose Jacobian is then asked for; and a deadline stops it the same way.
TEST(LevenbergMarquardt, AFailureWithAStopPendingIsAnInterruption) {
  const auto flag = std::make_shared<std::atomic<bool>>(false);
  const SolveMonitor monitor = SolveMonitor().with_cancel_flag(flag);
  int calls = 0, stop_at = 0;
  const ResidualFunction stoppable = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    if (++calls == stop_at) flag->store(true);
    return !monitor.stop_pending() && rosenbrock(x, r, jac);
  };
  for (const int at : {1, 4}) {
    flag->store(false);
    calls = 0;
    stop_at = at;
    const auto report =
        levenberg_marquardt(stoppable, Eigen::Vector2d(-1.2, 1.0), {.tolerance = 1e-13, .monitor = &monitor});
    EXPECT_EQ(report.status, Status::Interrupted) << report.message;
  }
  const SolveMonitor expired = SolveMonitor().with_deadline(std::chrono::steady_clock::now());
  EXPECT_TRUE(expired.stop_pending());
  const auto report = levenberg_marquardt(rosenbrock, Eigen::Vector2d(-1.2, 1.0), {.tolerance = 1e-13, .monitor = &expired});
  EXPECT_EQ(report.status, Status::Interrupted) << report.message;
  EXPECT_FALSE(SolveMonitor().stop_pending());
}

// The deadline is shared by every copy of a monitor (the stages of a solve): a solver's reserve for
// the work after a stop moves it earlier for all of them, and once passed it stays passed.
TEST(SolveMonitor, TheDeadlineLessTheReserveIsSharedByEveryStage) {
  const SolveMonitor base = SolveMonitor().with_deadline(std::chrono::steady_clock::now() + std::chrono::hours(1));
  const SolveMonitor stage = base.stage("shooting");
  EXPECT_FALSE(stage.stop_pending());
  stage.reserve_after_stop(std::chrono::hours(2));
  EXPECT_TRUE(base.deadline_passed());
  stage.reserve_after_stop(std::chrono::nanoseconds(0));
  EXPECT_TRUE(stage.stop_requested());  // expired stays expired
}

// A solve inside a timed solve (general::solve's Lie-group methods through transported::solve)
// sets its own deadline from the same time limit: it never outlives its caller's.
TEST(SolveMonitor, ANestedDeadlineNeverExtendsTheCallers) {
  const auto now = std::chrono::steady_clock::now();
  const SolveMonitor caller = SolveMonitor().with_deadline(now);
  EXPECT_TRUE(caller.with_deadline(now + std::chrono::hours(1)).stop_pending());
  const SolveMonitor later = SolveMonitor().with_deadline(now + std::chrono::hours(1));
  EXPECT_TRUE(later.with_deadline(now).stop_pending());  // an earlier deadline applies
}

TEST(LevenbergMarquardt, RejectsBadInput) {
  using testing::expect_invalid;
  const Eigen::Vector2d start(-1.2, 1.0);
  expect_invalid([&] { levenberg_marquardt(rosenbrock, start, {.tolerance = 0}); }, "tolerance = 0");
  expect_invalid([&] { levenberg_marquardt(rosenbrock, start, {.tolerance = std::nan("")}); }, "tolerance");
  expect_invalid([&] { levenberg_marquardt(rosenbrock, start, {.max_iterations = 0}); }, "max_iterations = 0");
  expect_invalid([&] { levenberg_marquardt(rosenbrock, start, {.fd_step = -1e-7}); }, "fd_step");
  expect_invalid([&] { levenberg_marquardt(rosenbrock, Eigen::Vector2d(1.0, INFINITY)); }, "x0");
  expect_invalid([&] { levenberg_marquardt(ResidualFunction{}, start); }, "f is empty");
}

}  // namespace
}  // namespace cartan::numerics
