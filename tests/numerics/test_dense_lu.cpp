// The blocked, stoppable dense LU (numerics/dense_lu.hpp) against Eigen's PartialPivLU: the same
// pivots, so the same factors up to rounding; its stop predicate and its zero pivots.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "cartan/numerics/dense_lu.hpp"
#include "test_support.hpp"

namespace cartan::numerics {
namespace {

Eigen::MatrixXd random_matrix(Eigen::Index m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Eigen::MatrixXd::NullaryExpr(m, m, [&] { return u(rng); });
}

// Sizes that are not multiples of the panel (64), one of a single panel and one below it; the
// factors (LU and the permutation) and the solution match Eigen's to 1e-12 relative.
TEST(BlockedLU, MatchesPartialPivLU) {
  std::mt19937 rng(cartan::testing::kSeed);
  for (const Eigen::Index m : {1, 5, 64, 300, 1000}) {
    const Eigen::MatrixXd a = random_matrix(m, rng);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(m, -1, 2);
    BlockedLU lu;
    lu.matrix() = a;
    ASSERT_EQ(lu.factorize(), BlockedLU::Outcome::Factorized) << m;
    const Eigen::PartialPivLU<Eigen::MatrixXd> reference(a);
    EXPECT_LE((lu.matrix() - reference.matrixLU()).cwiseAbs().maxCoeff(), 1e-12 * reference.matrixLU().cwiseAbs().maxCoeff())
        << m;
    const Eigen::VectorXd x = lu.solve(b), expected = reference.solve(b);
    EXPECT_LE((x - expected).norm(), 1e-12 * expected.norm()) << m;
    EXPECT_LE((a * x - b).norm(), 1e-12 * a.norm() * x.norm()) << m;
  }
}

// The predicate is called between panels and chunks of the trailing update: a true at its k-th
// call ends the factorisation there, for every k.
TEST(BlockedLU, StopsAtTheCallItsPredicateSaysSo) {
  std::mt19937 rng(cartan::testing::kSeed);
  BlockedLU lu;
  const Eigen::MatrixXd a = random_matrix(300, rng);
  lu.matrix() = a;
  int calls = 0;
  ASSERT_EQ(lu.factorize([&] { return ++calls, false; }), BlockedLU::Outcome::Factorized);
  EXPECT_GE(calls, 5);  // at least once per panel
  for (const int k : {1, 2, calls / 2, calls}) {
    lu.matrix() = a;
    int seen = 0;
    EXPECT_EQ(lu.factorize([&] { return ++seen == k; }), BlockedLU::Outcome::Stopped) << k;
    EXPECT_EQ(seen, k);
  }
}

// A zero column (it stays exactly zero through the updates) is a zero pivot; non-square is refused.
TEST(BlockedLU, ReportsASingularMatrix) {
  std::mt19937 rng(cartan::testing::kSeed);
  BlockedLU lu;
  lu.matrix() = random_matrix(200, rng);
  lu.matrix().col(130).setZero();
  EXPECT_EQ(lu.factorize(), BlockedLU::Outcome::Singular);
  EXPECT_EQ(lu.zero_pivot(), 130);
  lu.matrix() = Eigen::MatrixXd::Zero(1, 1);
  EXPECT_EQ(lu.factorize(), BlockedLU::Outcome::Singular);
  EXPECT_EQ(lu.zero_pivot(), 0);
  lu.matrix().resize(3, 4);
  EXPECT_THROW(lu.factorize(), std::invalid_argument);
}

}  // namespace
}  // namespace cartan::numerics
