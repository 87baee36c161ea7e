// The structured LU of the collocation Newton matrix (numerics/collocation_jacobian.hpp) against a
// dense partial-pivoting LU of the same matrix, and its singularity detection.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <random>
#include <string>
#include <utility>

#include "cartan/monitor.hpp"
#include "cartan/numerics/collocation_jacobian.hpp"
#include "test_support.hpp"

namespace cartan::numerics {
namespace {

CollocationJacobian random_jacobian(int n, int k, Eigen::Index m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  auto fill = [&](Eigen::MatrixXd& x) { x = x.unaryExpr([&](double) { return u(rng); }); };
  CollocationJacobian j;
  j.resize(n, k, m);
  for (auto* x : {&j.A, &j.B, &j.C, &j.Da, &j.Db, &j.Dp}) fill(*x);
  return j;
}

// Random blocks (so pivoting is exercised; the matrices are well conditioned with probability
// one): the solution matches Eigen's dense PartialPivLU to a residual of 1e-12 relative. The
// sizes include the fixed-size panels' ((n, k) = (2, 0), (2, 1), (6, 0)) and runtime-size ones (among them
// the generic transported systems' 12 and 24 states).
TEST(BlockLU, MatchesDenseLU) {
  std::mt19937 rng(cartan::testing::kSeed);
  for (auto [n, k, m] : {std::tuple{1, 0, 2}, {2, 0, 3}, {2, 1, 5}, {3, 2, 7}, {9, 0, 20}, {4, 3, 2}, {6, 0, 2},
                         {6, 0, 15}, {6, 1, 6}, {12, 0, 5}, {24, 0, 3}}) {
    const CollocationJacobian j = random_jacobian(n, k, m, rng);
    const Eigen::MatrixXd dense = j.sparse().toDense();
    Eigen::VectorXd b(dense.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(1.0 + static_cast<double>(i));
    BlockLU lu;
    ASSERT_TRUE(lu.factorize(j)) << lu.error();
    const Eigen::VectorXd x = lu.solve(b);
    const Eigen::VectorXd reference = dense.partialPivLu().solve(b);
    EXPECT_LE((dense * x - b).norm(), 1e-12 * b.norm() * dense.norm() * x.norm()) << n << " " << k << " " << m;
    EXPECT_LE((x - reference).norm(), 1e-8 * reference.norm()) << n << " " << k << " " << m;
  }
}

TEST(BlockLU, DetectsSingularMatrices) {
  std::mt19937 rng(cartan::testing::kSeed);
  CollocationJacobian j = random_jacobian(3, 1, 6, rng);
  j.Da.setZero();
  j.Db.setZero();
  j.Dp.setZero();  // no boundary conditions: rank deficient by n + k
  BlockLU lu;
  EXPECT_FALSE(lu.factorize(j));
  EXPECT_NE(lu.error().find("singular"), std::string::npos) << lu.error();
  EXPECT_FALSE(lu.stopped());
}

// The factorisation polls its stop predicate every steps_between_polls(n, k) steps: with a
// monitor's cancel flag raised it stops at the first poll (the flag lowered: the same matrix
// factorises).
TEST(BlockLU, StopsOnARaisedCancelFlag) {
  std::mt19937 rng(cartan::testing::kSeed);
  const Eigen::Index between_polls = BlockLU::steps_between_polls(6, 0);
  const CollocationJacobian j = random_jacobian(6, 0, 2 * between_polls + 10, rng);
  const auto flag = std::make_shared<std::atomic<bool>>(true);
  const SolveMonitor monitor = SolveMonitor().with_cancel_flag(flag);
  BlockLU lu;
  EXPECT_FALSE(lu.factorize(j, [&] { return monitor.poll(); }));
  EXPECT_TRUE(lu.stopped());
  EXPECT_EQ(lu.error(), "stopped at block " + std::to_string(between_polls - 1) + " (time limit or cancellation)");
  flag->store(false);
  const SolveMonitor fresh = SolveMonitor().with_cancel_flag(flag);
  EXPECT_TRUE(lu.factorize(j, [&] { return fresh.poll(); })) << lu.error();
  EXPECT_FALSE(lu.stopped());
}

// The polls are spaced by work, not by a count of steps: the same multiply-adds between two of
// them whatever the block size, so that large blocks (24 states: 41 472 a step) poll every few
// steps and small ones (2 states) do not pay a clock read a step.
TEST(BlockLU, PollsAtAboutTheSameWorkForEveryBlockSize) {
  for (const auto& [n, k] : {std::pair{2, 0}, {2, 1}, {6, 0}, {12, 0}, {24, 0}, {24, 3}, {60, 0}}) {
    const Eigen::Index per_step = Eigen::Index{n} * n * (3 * n + k);
    const Eigen::Index steps = BlockLU::steps_between_polls(n, k);
    EXPECT_GE(steps, 1);
    EXPECT_LE(steps * per_step, std::max(BlockLU::kMultiplyAddsBetweenPolls, per_step)) << n << " " << k;
    EXPECT_GT((steps + 1) * per_step, BlockLU::kMultiplyAddsBetweenPolls) << n << " " << k;
  }
  EXPECT_LE(BlockLU::steps_between_polls(24, 0), 8);
}

}  // namespace
}  // namespace cartan::numerics
