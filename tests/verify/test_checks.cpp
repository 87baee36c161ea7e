// The checks of include/cartan/verify/checks.hpp on synthetic trajectories: an exact solution
// gives rounding-level figures, and each kind of non-solution gives an O(1) figure in the check
// that should see it.
#include <gtest/gtest.h>

#include <cmath>

#include "cartan/models/rigid_body.hpp"
#include "cartan/verify/checks.hpp"
#include "test_support.hpp"

namespace cartan::verify {
namespace {

/// Samples g(t) = exp(angle(t) axis) at N + 1 uniform times on [0, T] with v = angle'(t) axis,
/// mu = I v, xi = 0.
template <class Angle, class Rate>
TransportedTrajectory<SO3> rotation_about(const SO3::Tangent& axis, double T, int N, Angle angle, Rate rate,
                                          const Eigen::Matrix3d& inertia) {
  TransportedTrajectory<SO3> x;
  for (int k = 0; k <= N; ++k) {
    const double t = T * k / N;
    x.t.push_back(t);
    x.g.push_back(SO3::exp(SO3::Tangent(angle(t) * axis)));
    x.v.push_back(rate(t) * axis);
    x.mu.push_back(inertia * x.v.back());
    x.xi.push_back(SO3::Tangent::Zero());
  }
  return x;
}

const SO3::Tangent kAxis = SO3::Tangent(1, 2, 2) / 3;

// Steady rotation about a principal axis of an isotropic body solves eq:reduced-system for every
// lambda (ad*_v I v = 0, P v = v since Ad(exp(-lambda t v)) v = v), and the piecewise geodesic
// through its samples is exactly stationary: every figure is rounding (1e-9 leaves room for the
// action's central difference, whose rounding is ~1e-16 |S| / epsilon = 1e-11 |S|).
TEST(VerifyChecks, ExactSolutionGivesRoundingLevelFigures) {
  const Eigen::Matrix3d inertia = 2 * Eigen::Matrix3d::Identity();
  for (double lambda : {0.0, 0.5, 1.0, 2.0}) {
    SCOPED_TRACE(lambda);
    const auto x = rotation_about(kAxis, 2.0, 50, [](double t) { return 0.7 * t; }, [](double) { return 0.7; }, inertia);
    const TrajectoryChecks<SO3, RigidBody> checks(RigidBody(inertia), lambda, 2.0, x);
    EXPECT_LT(checks.boundary_error(SO3::identity(), SO3::exp(SO3::Tangent(1.4 * kAxis))), 1e-14);
    EXPECT_LT(checks.legendre_residual(), 1e-15);
    EXPECT_LT(checks.energy_drift(), 1e-14);
    EXPECT_LT(checks.equation_residual().relative, 1e-12);
    EXPECT_LT(checks.action_stationarity(4, 1u), 1e-9);
    EXPECT_NEAR(checks.frequency(), 0.7, 1e-12);  // |u| = 0.7, no potential
    EXPECT_NEAR(checks.max_step(), 0.04, 1e-15);
  }
}

// An accelerating rotation angle(t) = t^2 with its true velocity 2t: g' = g v holds, but mu' = 2 I axis
// != 0 violates the momentum equation by the full size of its terms, the energy grows, and the path
// is not stationary (dS along w = sin(pi t / T) r is the integral of mu . w', a few percent of the
// size of its terms, since only r's component along the axis counts).
TEST(VerifyChecks, AcceleratingPathFailsResidualEnergyAndAction) {
  const Eigen::Matrix3d inertia = 2 * Eigen::Matrix3d::Identity();
  const auto x = rotation_about(kAxis, 2.0, 100, [](double t) { return t * t; }, [](double t) { return 2 * t; }, inertia);
  const TrajectoryChecks<SO3, RigidBody> checks(RigidBody(inertia), 0.0, 2.0, x);
  EXPECT_LT(checks.legendre_residual(), 1e-15);
  EXPECT_GT(checks.energy_drift(), 0.99);  // E = 4 t^2 from 0: drift / max E = 1
  const Residual r = checks.equation_residual();
  EXPECT_GT(r.relative, 0.1);  // mu' = 4 axis against 0, relative to |mu'| + |v| |mu| <= 4 + 32
  EXPECT_EQ(r.equation, "mu equation");
  EXPECT_GT(checks.action_stationarity(4, 1u), 1e-3);  // measured 0.018, against 1e-9 for the exact solution
}

// A velocity that disagrees with the path (v = 1.5 x the path's rate) fails the g equation, and a
// momentum that is not I v fails the Legendre check.
TEST(VerifyChecks, InconsistentVelocityAndMomentumAreSeen) {
  const Eigen::Matrix3d inertia = Eigen::Vector3d(2, 3, 4).asDiagonal();
  const SO3::Tangent e3 = SO3::Tangent::UnitZ();  // a principal axis: steady rotation is a solution
  auto x = rotation_about(e3, 1.0, 40, [](double t) { return t; }, [](double) { return 1.5; }, inertia);
  TrajectoryChecks<SO3, RigidBody> wrong_speed(RigidBody(inertia), 0.5, 1.0, x);
  EXPECT_NEAR(wrong_speed.equation_residual().relative, 0.5 / 2.5, 1e-9);  // |u - v| / (|u| + |v|)
  EXPECT_EQ(wrong_speed.equation_residual().equation, "g' = g P v");
  x.mu[20] *= 1.1;
  const TrajectoryChecks<SO3, RigidBody> wrong_momentum(RigidBody(inertia), 0.5, 1.0, x);
  EXPECT_NEAR(wrong_momentum.legendre_residual(), 0.1 * 6 / (6.6 + 6), 1e-12);  // |mu| = 4 * 1.5
}

// The three-point derivative is exact for quadratics on any mesh (second order).
TEST(VerifyChecks, ThreePointDerivativeIsExactForQuadratics) {
  auto f = [](double t) { return 3 * t * t - 2 * t + 1; };
  for (auto [t0, h1, h2] : {std::tuple{0.3, 0.1, 0.25}, std::tuple{-1.0, 0.5, 0.01}, std::tuple{2.0, 0.2, 0.2}}) {
    const ThreePoint d(h1, h2);
    EXPECT_NEAR(d.a * f(t0 - h1) + d.b * f(t0) + d.c * f(t0 + h2), 6 * t0 - 2, 1e-11);
  }
}

TEST(VerifyChecks, UniformMeshes) {
  EXPECT_TRUE(is_uniform({0.0, 0.5, 1.0, 1.5}));
  EXPECT_FALSE(is_uniform({0.0, 0.4, 1.0, 1.5}));
  EXPECT_FALSE(is_uniform({0.0}));
  EXPECT_EQ(relative_to(0.0, 0.0), 0.0);
  EXPECT_NEAR(discretisation_threshold(2.0, 0.1, 2), 0.02, 1e-15);
}

}  // namespace
}  // namespace cartan::verify
