// Single shooting's compiled bookkeeping (solvers/shooting.hpp) on a toy kernel with no group or
// manifold: the result's counters are the driver's, its status the driver's, its message names the
// kernel's label; and the auxiliary's unit (principle/scales.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "cartan/principle/scales.hpp"
#include "cartan/solvers/shooting.hpp"

namespace cartan::solvers {
namespace {

/// r_i(y) = y_i^3 - c_i, y = (v0 (2), a0 (2)): the root y_i = cbrt(c_i), reached by
/// Levenberg–Marquardt in a few iterations from y = 1.
class CubicKernel : public numerics::ShootingKernel {
 public:
  Eigen::Vector4d c{8, 27, 1, 0.125};
  numerics::SweepEnd sweep(const Eigen::VectorXd& y, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, int, double,
                           std::string&) override {
    r = y.array().cube().matrix() - c;
    if (jacobian != nullptr) *jacobian = (3 * y.array().square()).matrix().asDiagonal();
    return numerics::SweepEnd::Done;
  }
  bool record_result(const Eigen::VectorXd&, int) override { return true; }
};

TEST(Shoot, TheResultTakesTheDriversCountersStatusAndWords) {
  for (bool analytic : {true, false}) {
    CubicKernel kernel;
    ShootingOptions options;
    options.analytic_jacobian = analytic;
    options.tolerance = 1e-12;
    ResultCore result;
    const numerics::ShootingOutcome outcome =
        shoot(kernel, 2, 3.0, 0.5, 0.0, options, Eigen::Vector4d::Ones(), {"toy shooting", "exact", "a", ", toy"}, result);
    ASSERT_EQ(outcome.status, Status::Converged) << outcome.summary();
    EXPECT_EQ(result.status, Status::Converged);
    // The root in the problem's units: cbrt(c) to the tolerance (the dimensionless residual is
    // (r_v, r_a / s), the Jacobian near the root diag(3 cbrt(c)^2) >= 0.75).
    EXPECT_NEAR((outcome.y - Eigen::Vector4d(2, 3, 1, 0.5)).cwiseAbs().maxCoeff(), 0, 1e-11);
    EXPECT_EQ(result.inner_iterations, outcome.report.iterations);
    EXPECT_GT(result.inner_iterations, 1);
    EXPECT_EQ(result.residual_history, outcome.report.residual_history);
    EXPECT_EQ(result.sweeps, outcome.sweeps);
    EXPECT_EQ(result.message, std::string("toy shooting (") + (analytic ? "exact" : "finite-difference") +
                                  " Jacobian, a scale 0.5, toy): " + outcome.summary());
  }
}

TEST(Shoot, AFailureIsTheDriversStatusWithItsWords) {
  CubicKernel kernel;
  ShootingOptions options;
  options.max_iterations = 1;
  ResultCore result;
  const numerics::ShootingOutcome outcome =
      shoot(kernel, 2, 1.0, 1.0, 0.0, options, Eigen::Vector4d::Ones(), {"shooting", "analytic", "xi", ""}, result);
  EXPECT_EQ(result.status, Status::MaxIterations);
  EXPECT_EQ(result.status, outcome.status);
  EXPECT_FALSE(result.converged());
  EXPECT_EQ(result.message.rfind("shooting (analytic Jacobian, xi scale 1): max-iterations", 0), 0u) << result.message;
}

TEST(Shoot, TheAuxiliarysUnitIsTVMuOrOne) {
  EXPECT_EQ(aux_scale(2, 3, 4), 24.0);
  EXPECT_EQ(aux_scale(2, 0, 4), 1.0);  // g0 = gT with no fallback velocity, or a Lagrangian without momentum
  EXPECT_EQ(aux_scale(2, std::numeric_limits<double>::infinity(), 4), 1.0);
  EXPECT_EQ(aux_scale(2, std::nan(""), 4), 1.0);
  EXPECT_EQ(aux_scale(1e-200, 1e-200, 1), 1.0);  // below the smallest normal number
}

}  // namespace
}  // namespace cartan::solvers
