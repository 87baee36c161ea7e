// The not-a-knot cubic spline (numerics/cubic_spline.hpp): it reproduces cubics exactly (the
// not-a-knot conditions hold for any cubic, and the spline is unique), the parabola through three
// points and the line through two; it interpolates its nodes and is C^2 in between.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cartan/numerics/cubic_spline.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

/// Two cubics side by side (rows), at the nodes t.
Eigen::MatrixXd cubics(const Eigen::VectorXd& t) {
  Eigen::MatrixXd y(2, t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    y(0, i) = 1 - 2 * t[i] + 0.5 * t[i] * t[i] + 0.25 * t[i] * t[i] * t[i];
    y(1, i) = -3 + t[i] * t[i] * t[i];
  }
  return y;
}

/// Strictly increasing nodes in [0, 2] with spacings varying by a factor up to 20 (so that the
/// not-a-knot rows are far from diagonally dominant and the elimination must pivot).
Eigen::VectorXd uneven_nodes(int m, std::mt19937& rng) {
  std::uniform_real_distribution<double> spacing(0.05, 1.0);
  Eigen::VectorXd t(m);
  t[0] = 0;
  for (int i = 1; i < m; ++i) t[i] = t[i - 1] + spacing(rng);
  return 2 * t / t[m - 1];
}

TEST(NotAKnotSpline, ReproducesCubicsExactly) {
  std::mt19937 rng(kSeed);
  for (int m : {4, 5, 7, 12, 50, 400}) {
    const Eigen::VectorXd t = uneven_nodes(m, rng);
    const numerics::CubicHermite spline = numerics::not_a_knot_spline(t, cubics(t));
    Eigen::VectorXd probe = Eigen::VectorXd::LinSpaced(97, 0, 2);
    // Rounding of the slopes' elimination: entries of size ~10, spacings down to 1e-3 at m = 400.
    EXPECT_NEAR_MATRIX(spline.values(probe), cubics(probe), 1e-11) << "m = " << m;
    Eigen::MatrixXd slopes(2, probe.size());
    for (Eigen::Index j = 0; j < probe.size(); ++j) slopes.col(j) = spline.derivative(probe[j]);
    const Eigen::ArrayXd x = probe.array();
    Eigen::MatrixXd exact(2, probe.size());
    exact.row(0) = (-2 + x + 0.75 * x * x).matrix().transpose();
    exact.row(1) = (3 * x * x).matrix().transpose();
    EXPECT_NEAR_MATRIX(slopes, exact, 1e-9) << "m = " << m;
  }
}

TEST(NotAKnotSpline, ThreePointsGiveTheParabolaAndTwoTheLine) {
  Eigen::VectorXd t(3);
  t << 0, 0.3, 1.1;
  Eigen::MatrixXd y(1, 3);
  for (int i = 0; i < 3; ++i) y(0, i) = 2 - t[i] + 4 * t[i] * t[i];
  const auto parabola = numerics::not_a_knot_spline(t, y);
  for (double x : {0.1, 0.5, 0.9}) EXPECT_NEAR(parabola.value(x)[0], 2 - x + 4 * x * x, 1e-14);
  // Spacings above 1 make the parabola's first row (1, 1) the smaller pivot: the elimination swaps rows.
  const Eigen::Vector3d wide(0, 5, 12);
  Eigen::MatrixXd wide_y(1, 3);
  for (int i = 0; i < 3; ++i) wide_y(0, i) = 2 - wide[i] + 4 * wide[i] * wide[i];
  const auto wide_parabola = numerics::not_a_knot_spline(wide, wide_y);
  for (double x : {1.0, 7.5, 11.0}) EXPECT_NEAR(wide_parabola.value(x)[0], 2 - x + 4 * x * x, 1e-12);
  const auto line = numerics::not_a_knot_spline(t.head(2), y.leftCols(2));
  EXPECT_NEAR(line.value(0.2)[0], y(0, 0) + (y(0, 1) - y(0, 0)) * 0.2 / 0.3, 1e-14);
  EXPECT_NEAR(line.derivative(0.1)[0], (y(0, 1) - y(0, 0)) / 0.3, 1e-13);
}

TEST(NotAKnotSpline, InterpolatesAndIsTwiceContinuouslyDifferentiable) {
  std::mt19937 rng(kSeed + 1);
  const Eigen::VectorXd t = uneven_nodes(9, rng);
  Eigen::MatrixXd y(1, 9);
  for (int i = 0; i < 9; ++i) y(0, i) = std::sin(3 * t[i]);
  const auto spline = numerics::not_a_knot_spline(t, y);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(spline.value(t[i])[0], y(0, i));
  // Second derivative from both sides of each interior node, by differences of S' (step 1e-7:
  // truncation ~1e-7 |S'''|, rounding ~1e-9 / 1e-7): equal to 1e-5.
  for (int i = 1; i < 8; ++i) {
    const double e = 1e-7;
    const double left = (spline.derivative(t[i] - e)[0] - spline.derivative(t[i] - 2 * e)[0]) / e;
    const double right = (spline.derivative(t[i] + 2 * e)[0] - spline.derivative(t[i] + e)[0]) / e;
    EXPECT_NEAR(left, right, 1e-5) << "node " << i;
  }
}

TEST(NotAKnotSpline, BadInputIsRefusedByName) {
  Eigen::VectorXd t(3);
  t << 0, 1, 1;
  expect_invalid([&] { (void)numerics::not_a_knot_spline(t, Eigen::MatrixXd::Zero(1, 3)); }, {"t[2] = 1", "greater"});
  expect_invalid([&] { (void)numerics::not_a_knot_spline(t.head(1), Eigen::MatrixXd::Zero(1, 1)); }, "t.size() = 1");
  expect_invalid([&] { (void)numerics::not_a_knot_spline(Eigen::Vector3d(0, 1, 2), Eigen::MatrixXd::Zero(1, 2)); }, "y.cols()");
}

}  // namespace
}  // namespace cartan::testing
