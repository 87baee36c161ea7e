// The shooting driver (numerics/shooting_driver.hpp) on toy kernels with known roots: its scaling
// of the unknowns and residual, which sweeps record and which buffer holds the result, and what a
// stop, a failed recording sweep and an undefined residual leave.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "cartan/monitor.hpp"
#include "cartan/numerics/shooting_driver.hpp"
#include "test_support.hpp"

namespace cartan::numerics {
namespace {

/// r(y) = A y - b in the problem's units, y = (v0 (2), a0 (2)); the sweep "records" y into a
/// buffer, so that the result's buffer can be checked against the result's point.
class LinearShootingKernel : public ShootingKernel {
 public:
  Eigen::Matrix4d A;
  Eigen::Vector4d b;
  std::array<Eigen::VectorXd, 2> buffers;
  std::vector<int> slots;          ///< the slot of every sweep
  Eigen::VectorXd result;          ///< what record_result made the result
  int recording_sweeps = 0;        ///< record_result's own sweeps (slot < 0)
  bool fail_recording = false;
  int stop_after_sweeps = -1;      ///< >= 0: every sweep from this one on fails (a stop)

  LinearShootingKernel() {
    A << 4, 1, 0, 0.5, 1, 3, 0.2, 0, 0, 0.2, 2, 0.1, 0.5, 0, 0.1, 1;
    b << 1, -2, 0.5, 3;
  }
  SweepEnd sweep(const Eigen::VectorXd& y, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, int slot, double,
                 std::string& failure) override {
    slots.push_back(slot);
    if (stop_after_sweeps >= 0 && static_cast<int>(slots.size()) > stop_after_sweeps) {
      failure = "stopped";
      return SweepEnd::Failed;
    }
    r = A * y - b;
    if (jacobian != nullptr) *jacobian = A;
    if (slot >= 0) buffers[static_cast<std::size_t>(slot)] = y;
    return SweepEnd::Done;
  }
  bool record_result(const Eigen::VectorXd& y, int slot) override {
    if (slot < 0) ++recording_sweeps;
    if (fail_recording) return false;
    result = slot >= 0 ? buffers[static_cast<std::size_t>(slot)] : y;
    return true;
  }
};

ShootingDriverOptions driver_options(bool analytic) {
  ShootingDriverOptions o;
  o.velocity_size = 2;
  o.horizon = 7.0;
  o.aux_scale = 0.01;
  o.analytic_jacobian = analytic;
  o.solver.tolerance = 1e-13;
  return o;
}

// The root of the linear system whatever the scales T and s (the dimensionless problem has the
// same root); the scaled residual (r_q, a_N / s) is what the tolerance bounds, so |A y - b| is
// within 1e-13 max(1, s) = 1e-13 and y within cond(A) times that.
TEST(ShootingDriver, FindsTheRootInTheProblemsUnits) {
  for (bool analytic : {true, false}) {
    LinearShootingKernel kernel;
    const ShootingOutcome outcome = shoot(kernel, driver_options(analytic), Eigen::Vector4d(1, 1, 1, 1));
    ASSERT_EQ(outcome.status, Status::Converged) << outcome.summary();
    const Eigen::Vector4d root = kernel.A.lu().solve(kernel.b);
    EXPECT_LT((outcome.y - root).norm(), 1e-12);
    ASSERT_TRUE(outcome.has_trajectory);
    EXPECT_EQ(kernel.result, outcome.y);  // the result's buffer holds the result's point, bit for bit
    // Analytic: every sweep records and the result needs no sweep of its own; differences: none
    // records and the result is swept once more.
    EXPECT_EQ(kernel.recording_sweeps, analytic ? 0 : 1);
    for (int slot : kernel.slots) EXPECT_EQ(slot >= 0, analytic);
    EXPECT_EQ(outcome.sweeps, static_cast<int>(kernel.slots.size()) + kernel.recording_sweeps);
  }
}

// A stop before any sweep completed leaves no trajectory and no sweep after the stop; a stop after
// one leaves the best point's recorded trajectory.
TEST(ShootingDriver, AStopLeavesTheBestRecordedPointOrNothing) {
  const SolveMonitor stopped([](const Progress&) {}, [] { return true; });
  for (int completed : {0, 1}) {
    LinearShootingKernel kernel;
    kernel.stop_after_sweeps = completed;
    ShootingDriverOptions o = driver_options(true);
    o.solver.monitor = &stopped;
    const ShootingOutcome outcome = shoot(kernel, o, Eigen::Vector4d(1, 1, 1, 1));
    EXPECT_EQ(outcome.status, Status::Interrupted) << outcome.summary();
    if (completed == 0) {
      EXPECT_TRUE(outcome.stopped_before_a_sweep);
      EXPECT_FALSE(outcome.has_trajectory);
      EXPECT_EQ(kernel.recording_sweeps, 0);
    } else {
      ASSERT_TRUE(outcome.has_trajectory);
      EXPECT_EQ(kernel.result, Eigen::VectorXd(Eigen::Vector4d(1, 1, 1, 1)));
      EXPECT_EQ(kernel.recording_sweeps, 0);
    }
  }
}

// A result whose recording sweep fails is NonFinite with no trajectory, whatever LM found.
TEST(ShootingDriver, AFailedRecordingSweepIsNonFinite) {
  LinearShootingKernel kernel;
  kernel.fail_recording = true;
  const ShootingOutcome outcome = shoot(kernel, driver_options(false), Eigen::Vector4d(1, 1, 1, 1));
  EXPECT_EQ(outcome.report.status, Status::Converged);
  EXPECT_EQ(outcome.status, Status::NonFinite);
  EXPECT_FALSE(outcome.has_trajectory);
}

TEST(ShootingDriver, RejectsBadOptions) {
  LinearShootingKernel kernel;
  ShootingDriverOptions o = driver_options(true);
  o.velocity_size = 4;
  cartan::testing::expect_invalid([&] { shoot(kernel, o, Eigen::Vector4d::Zero()); }, "velocity_size = 4");
  o = driver_options(true);
  o.aux_scale = 0;
  cartan::testing::expect_invalid([&] { shoot(kernel, o, Eigen::Vector4d::Zero()); }, "aux_scale = 0");
  o.aux_scale = 1;
  o.aux_size = -1;
  cartan::testing::expect_invalid([&] { shoot(kernel, o, Eigen::Vector4d::Zero()); }, "aux_size = -1");
  cartan::testing::expect_invalid([&] { shoot(kernel, driver_options(true), Eigen::Vector4d(1, NAN, 0, 0)); }, "y0");
}

}  // namespace
}  // namespace cartan::numerics
