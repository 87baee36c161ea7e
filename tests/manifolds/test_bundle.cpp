// The horizontal differential on a vector bundle with a linear connection (eq:hor-diff-local,
// manifolds/bundle.hpp): it reduces to eq:hor-diff-1 on TM and eq:hor-diff-2 on T*M, it is the
// derivative along horizontal lifts (lem:horizontal-differential, hor-diff-curve) on a rank-2
// bundle over R^2 that is not a tangent bundle, and the bundles' transports are the manifolds'.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "kernels/manifold/hamilton_cases.hpp"
#include "mechanics/mechanics_support.hpp"

namespace cartan::testing {
namespace {

using manifolds::LinearBundle;
using Vec2 = Eigen::Vector2d;

/// Two points with arguments (x, u, dF/dx, dF/du) in the charts of hamilton_cases.hpp, for which
/// `check` compares the bundle formula with a chart formula.
template <class Check>
void for_each_chart_and_argument(const Check& check) {
  std::mt19937 rng(kSeed + 140);
  const auto run = [&](const std::string& what, const auto& manifold) {
    for (int trial = 0; trial < 2; ++trial) {
      check(what, manifold, random_vector<Vec2>(rng, 0.8), random_vector<Vec2>(rng, 1.5), random_vector<Vec2>(rng, 1.0),
            random_vector<Vec2>(rng, 1.0));
    }
  };
  for (const auto& [name, chart] : sphere_connections()) run("sphere, " + name, chart);
  run("R^2, torsion and curvature", skew_euclidean());
}

// The bundle formula and the chart formulas sum the same products in another order: they agree
// to a few ulps of the O(1) terms (1e-14).
TEST(Bundle, ReducesToTheTangentAndCotangentFormulas) {
  for_each_chart_and_argument([](const std::string& what, const auto& manifold, const Vec2& x, const Vec2& u, const Vec2& dx,
                                 const Vec2& du) {
    EXPECT_LE(max_abs_diff(manifolds::horizontal_differential(manifolds::tangent_bundle(manifold), x, u, dx, du),
                           manifolds::tangent_horizontal_differential(manifold, x, u, dx, du)),
              1e-14)
        << what << " (eq:hor-diff-1)";
    EXPECT_LE(max_abs_diff(manifolds::horizontal_differential(manifolds::cotangent_bundle(manifold), x, u, dx, du),
                           manifolds::cotangent_horizontal_differential(manifold, x, u, dx, du)),
              1e-14)
        << what << " (eq:hor-diff-2)";
  });
}

// The TM bundle transports vectors as the manifold does (transport_along_step), and the T*M bundle
// by the inverse transpose, which preserves pairings. With the T*M coefficients as printed
// (A_i = +Gamma_i^T, docs/paper-notes.md#erratum-8) the pairing is not preserved. RK4 with 1000 steps
// over a line of length <= 1.4, |Gamma| <= 3 (error ~1000 (4e-3)^5 / 120 ~ 1e-11) against the chart's own
// transport (error ~1e-11): tolerance 1e-9.
TEST(Bundle, TransportIsTheManifoldsTransport) {
  for_each_chart_and_argument([](const std::string& what, const auto& manifold, const Vec2& x, const Vec2& u, const Vec2& p,
                                 const Vec2& direction) {
    const auto line = [&](double s) { return Vec2(x + s * direction); };
    const auto velocity = [&](double) { return direction; };
    const Eigen::Matrix2d P = manifold.transport_along_step(x, direction);
    const Vec2 u1 = manifolds::transport_fibre(manifolds::tangent_bundle(manifold), line, velocity, u, 1.0, 1000);
    const Vec2 p1 = manifolds::transport_fibre(manifolds::cotangent_bundle(manifold), line, velocity, p, 1.0, 1000);
    EXPECT_LE(max_abs_diff(u1, P * u), 1e-9) << what << " (TM)";
    EXPECT_LE(std::abs(p1.dot(u1) - p.dot(u)), 1e-9) << what << " (T*M pairing)";
    const LinearBundle<2, 2> printed([&](const Vec2& y) {
      auto a = manifolds::christoffel_matrices(manifold, y);
      for (auto& m : a) m = Eigen::Matrix2d(m.transpose());
      return a;
    });
    const Vec2 p_printed = manifolds::transport_fibre(printed, line, velocity, p, 1.0, 1000);
    EXPECT_GE(std::abs(p_printed.dot(u1) - p.dot(u)), 1e-3) << what << " (printed T*M coefficients)";
  });
}

/// A rank-2 bundle over R^2 with coefficients A_i(x) that are no Christoffel symbols of anything.
LinearBundle<2, 2> rank_two_bundle() {
  return LinearBundle<2, 2>([](const Vec2& x) {
    LinearBundle<2, 2>::Coefficients a;
    a[0] << std::sin(x.x()) + 0.3, x.y() * x.y(), -0.7 * std::cos(x.x() * x.y()), 0.2 + x.x();
    a[1] << 0.5 * x.x(), -0.4 + std::exp(0.3 * x.y()), 0.9, std::sin(x.x() - x.y());
    return a;
  });
}

/// A function on the total space.
double fibre_function(const Vec2& x, const Vec2& u) {
  return std::sin(x.x()) * u.x() * u.x() + x.y() * u.x() * u.y() + std::exp(0.3 * u.y()) * std::cos(x.y()) + x.x() * x.y();
}

// lem:horizontal-differential, (hor-diff-curve): d/de F(transport of u from t to t + e along
// gamma) = d^Gamma F(gamma'(t)) on a curved base curve at t = 0.4. Fourth-order differences with
// step 1e-3 (error ~1e-12) of a transport by RK4 in 8 steps over |e| <= 2e-3 (error ~1e-20), and
// second-order differences with step 1e-5 for dF/dx, dF/du (error ~1e-11 + rounding 1e-11):
// tolerance 1e-9; the connection term itself is >= 1e-3 here (measured 7e-3 to 0.5), so dropping
// it fails by a million tolerances.
TEST(Bundle, HorizontalDifferentialIsTheDerivativeAlongHorizontalLifts) {
  std::mt19937 rng(kSeed + 141);
  const LinearBundle<2, 2> bundle = rank_two_bundle();
  for (int trial = 0; trial < 4; ++trial) {
    const Vec2 x0 = random_vector<Vec2>(rng, 1.0), a = random_vector<Vec2>(rng, 1.0), b = random_vector<Vec2>(rng, 1.0);
    const Vec2 u = random_vector<Vec2>(rng, 1.5);
    const double t = 0.4;
    const auto curve = [&](double s) { return Vec2(x0 + s * a + s * s * b); };
    const auto velocity = [&](double s) { return Vec2(a + 2 * s * b); };
    const double along_lift = derivative(
        [&](double e) {
          const auto shifted = [&](double s) { return curve(t + s); };
          const auto shifted_velocity = [&](double s) { return velocity(t + s); };
          return fibre_function(curve(t + e), manifolds::transport_fibre(bundle, shifted, shifted_velocity, u, e, 8));
        },
        1e-3);
    const Vec2 x = curve(t);
    const Vec2 dF_dx = vector_gradient_fd<Vec2>([&](const Vec2& y) { return fibre_function(y, u); }, x, 1e-5);
    const Vec2 dF_du = vector_gradient_fd<Vec2>([&](const Vec2& v) { return fibre_function(x, v); }, u, 1e-5);
    const Vec2 horizontal = manifolds::horizontal_differential(bundle, x, u, dF_dx, dF_du);
    EXPECT_NEAR(horizontal.dot(velocity(t)), along_lift, 1e-9) << "trial " << trial;
    const double connection_term = (horizontal - dF_dx).dot(velocity(t));
    std::cout << "[ measured ] trial " << trial << ": d^Gamma F(gamma') = " << along_lift
              << ", connection term " << connection_term << '\n';
    EXPECT_GE(std::abs(connection_term), 1e-3) << "trial " << trial;
  }
}

TEST(Bundle, RejectsAnEmptyCoefficientField) {
  expect_invalid([] { return LinearBundle<2, 2>(LinearBundle<2, 2>::CoefficientField()); }, {"coefficients", "empty"});
}

}  // namespace
}  // namespace cartan::testing
