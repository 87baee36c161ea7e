// The two-level scheme's compiled driver (solvers/two_level.hpp) on a toy fixed-point system with
// no group: the inner problem v^2 = 1 + s (residual v^2 - 1 - s), the update s <- v / 4, whose
// fixed point is v = (1 + sqrt(65)) / 8 (v^2 = 1 + v / 4); the outer change contracts by about
// 1 / (8 v) per iteration.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cartan/solvers/two_level.hpp"

namespace cartan::solvers {
namespace {

struct ToyFixedPoint final : FixedPointSystem {
  ResultCore& result;
  double s = 0;
  int inner_fails_from = 1 << 30;  ///< inner evaluations after this many fail
  bool update_fails = false;
  double gain = 1;  ///< K: inner v^2 = 1 + K s, update s <- v / (4 K): the same fixed point, a change K times smaller
  int evaluations = 0;
  std::string why;

  explicit ToyFixedPoint(ResultCore& r) : result(r) {}
  bool inner(const Eigen::VectorXd& v, Eigen::VectorXd& r, Eigen::MatrixXd* jac) override {
    if (++evaluations > inner_fails_from) {
      why = "the toy sweep failed";
      return false;
    }
    r = Eigen::VectorXd::Constant(1, v[0] * v[0] - 1 - gain * s);
    if (jac) *jac = Eigen::MatrixXd::Constant(1, 1, 2 * v[0]);
    return true;
  }
  std::optional<double> update(const Eigen::VectorXd& v) override {
    if (update_fails) {
      why = "the rates sweep failed";
      return std::nullopt;
    }
    const double next = v[0] / (4 * gain), change = std::abs(next - s);
    s = next;
    return change;
  }
  bool record(const Eigen::VectorXd& v) override {
    result.terminal_error = std::abs(v[0] * v[0] - 1 - gain * s);
    return true;
  }
  const std::string& failure() const override { return why; }
};

TEST(FixedPointDriver, ConvergesToTheFixedPointAndCountsBothLoops) {
  for (const bool analytic : {false, true}) {
    ResultCore r;
    ToyFixedPoint toy(r);
    solve_fixed_point(toy, {.tolerance = 1e-12, .analytic_jacobian = analytic}, Eigen::VectorXd::Constant(1, 1.0), r);
    EXPECT_EQ(r.status, Status::Converged) << r.message;
    EXPECT_NEAR(4 * toy.s, (1 + std::sqrt(65.0)) / 8, 1e-11);  // v at the fixed point, to the outer tolerance
    EXPECT_EQ(static_cast<int>(r.residual_history.size()), r.outer_iterations);
    EXPECT_LT(r.residual_history.back(), 1e-12);
    // Every inner evaluation (finite differences: 2 per Jacobian), one rates sweep per outer
    // iteration, one to record.
    EXPECT_EQ(r.sweeps, toy.evaluations + r.outer_iterations + 1);
    EXPECT_EQ(r.message.rfind("two-level: converged after ", 0), 0u) << r.message;
  }
}

// A strongly coupled sequence (K = 1e6): the outer change falls below tol while the end point of
// the updated sequence is still ~K tol off. Converged only once the end point meets tol too (SE(2),
// inertia (1, 100, 1e4), lambda = 2 returned "converged" 1.7e-8 off before).
TEST(FixedPointDriver, ConvergedMeansTheEndPointMeetsTheToleranceToo) {
  ResultCore r;
  ToyFixedPoint toy(r);
  toy.gain = 1e6;
  solve_fixed_point(toy, {.tolerance = 1e-12}, Eigen::VectorXd::Constant(1, 1.0), r);
  EXPECT_EQ(r.status, Status::Converged) << r.message;
  EXPECT_LE(r.terminal_error, 1e-12) << r.message;
  EXPECT_NEAR(4 * toy.gain * toy.s, (1 + std::sqrt(65.0)) / 8, 1e-11);
}

TEST(FixedPointDriver, EachLoopsFailureHasItsStatus) {
  ResultCore outer;
  ToyFixedPoint slow(outer);
  solve_fixed_point(slow, {.tolerance = 1e-12, .max_outer = 2}, Eigen::VectorXd::Constant(1, 1.0), outer);
  EXPECT_EQ(outer.status, Status::OuterNotConverged);
  EXPECT_EQ(outer.outer_iterations, 2);

  ResultCore inner;
  ToyFixedPoint broken(inner);
  broken.inner_fails_from = 0;
  solve_fixed_point(broken, {}, Eigen::VectorXd::Constant(1, 1.0), inner);
  EXPECT_EQ(inner.status, Status::InnerNotConverged);
  EXPECT_NE(inner.message.find("last failed sweep: the toy sweep failed"), std::string::npos) << inner.message;

  ResultCore rates;
  ToyFixedPoint no_rates(rates);
  no_rates.update_fails = true;
  solve_fixed_point(no_rates, {}, Eigen::VectorXd::Constant(1, 1.0), rates);
  EXPECT_EQ(rates.status, Status::NonFinite);
  EXPECT_NE(rates.message.find("the sweep for the xi rates failed in outer iteration 1: the rates sweep failed"),
            std::string::npos) << rates.message;
}

}  // namespace
}  // namespace cartan::solvers
