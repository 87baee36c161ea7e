// Multiple shooting's compiled driver (solvers/multiple_shooting.hpp) on a toy lifted system with
// no group: x = (a, b), r = (a^2 - 2, b - a), whose root is a = b = sqrt(2); "one plain sweep" from
// x has the residual |a^2 - 2| scaled by `inflation` (a sweep amplifies the joins' defects).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cartan/solvers/multiple_shooting.hpp"

namespace cartan::solvers {
namespace {

struct ToyLifted final : LiftedSystem {
  ResultCore& result;
  double inflation = 1;
  bool start_fails = false;
  int recentred = 0;
  std::string why;

  explicit ToyLifted(ResultCore& r) : result(r) {}
  std::optional<Eigen::VectorXd> initialise() override {
    if (start_fails) {
      why = "the sweep from the guess failed";
      return std::nullopt;
    }
    return Eigen::Vector2d(1, 0);
  }
  void recentre(Eigen::VectorXd&) override { ++recentred; }
  bool evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* jac) override {
    r = Eigen::Vector2d(x[0] * x[0] - 2, x[1] - x[0]);
    if (jac) *jac = (Eigen::Matrix2d() << 2 * x[0], 0, -1, 1).finished();
    return true;
  }
  double single_sweep_residual(const Eigen::VectorXd& x) override { return inflation * std::abs(x[0] * x[0] - 2); }
  bool record(const Eigen::VectorXd& x) override {
    result.terminal_error = single_sweep_residual(x);
    result.xi_terminal = 0;
    return true;
  }
  double auxiliary_scale() const override { return 1; }
  const std::string& failure() const override { return why; }
};

TEST(LiftedDriver, ConvergesAndCountsItsSweeps) {
  ResultCore r;
  ToyLifted toy(r);
  solve_lifted(toy, {.segments = 2, .tolerance = 1e-12}, "toy: ", r);
  EXPECT_EQ(r.status, Status::Converged) << r.message;
  EXPECT_LE(r.terminal_error, 1e-12);
  EXPECT_EQ(r.message.rfind("toy: ", 0), 0u);
  // One sweep for the references (2 segments), one per evaluation (LM's, one per history entry
  // and Jacobian), one plain sweep to check, one to record.
  EXPECT_GE(r.sweeps, r.inner_iterations + 3);
  EXPECT_EQ(static_cast<int>(r.residual_history.size()), r.inner_iterations + 1);
}

TEST(LiftedDriver, RecentresBetweenRoundsAndKeepsOneHistory) {
  ResultCore r;
  ToyLifted toy(r);
  solve_lifted(toy, {.tolerance = 1e-12, .recentre_every = 1}, "", r);  // one iteration per round
  EXPECT_EQ(r.status, Status::Converged) << r.message;
  EXPECT_EQ(toy.recentred, r.inner_iterations - 1);  // between rounds, not after the last
  // A round's first point repeats the last one of the previous round: recorded once.
  EXPECT_EQ(static_cast<int>(r.residual_history.size()), r.inner_iterations + 1);
}

TEST(LiftedDriver, ASweepThatAmplifiesTheJoinsIsInconsistentAfterThreeTightenings) {
  ResultCore r;
  ToyLifted toy(r);
  toy.inflation = 1e20;  // no lifted tolerance above rounding makes the plain sweep meet 1e-8
  solve_lifted(toy, {.tolerance = 1e-8}, "", r);
  EXPECT_EQ(r.status, Status::Inconsistent) << r.message;
  EXPECT_NE(r.message.find("single sweep from v0: terminal error"), std::string::npos);
}

TEST(LiftedDriver, AFailedStartIsNonFiniteOrInterrupted) {
  ResultCore r;
  ToyLifted toy(r);
  toy.start_fails = true;
  solve_lifted(toy, {.segments = 3}, "toy: ", r);
  EXPECT_EQ(r.status, Status::NonFinite);
  EXPECT_EQ(r.message, "toy: the initial segment states failed: the sweep from the guess failed");
  ResultCore stopped;
  ToyLifted again(stopped);
  again.start_fails = true;
  const SolveMonitor monitor(nullptr, [] { return true; });
  solve_lifted(again, {.monitor = &monitor}, "", stopped);
  EXPECT_EQ(stopped.status, Status::Interrupted);
}

}  // namespace
}  // namespace cartan::solvers
