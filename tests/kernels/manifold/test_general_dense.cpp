// Dense output of a general solution (kernels/manifold/dense.hpp) on the sphere against the closed form of
// a great circle travelled at constant speed: the piece through consecutive nodes is that circle,
// so positions and the transported frame are exact between the nodes; nodes come back bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cartan/kernels/manifold/dense.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

TEST(GeneralDenseOutput, ExactOnAGreatCircle) {
  const manifolds::Sphere sphere;
  const Eigen::Vector3d q0(1, 0, 0), e1(0, 0.6, 0.8), e2 = q0.cross(e1);
  const double w = std::numbers::pi / 3;  // rad per unit time; steps of at most 0.35 rad
  const auto point = [&](double t) -> Eigen::Vector3d { return std::cos(w * t) * q0 + std::sin(w * t) * e1; };
  const auto frame = [&](double t) {
    manifolds::Sphere::Frame e;
    e.col(0) = -std::sin(w * t) * q0 + std::cos(w * t) * e1;
    e.col(1) = e2;
    return e;
  };
  general::GeneralTrajectory<manifolds::Sphere> x;
  for (double t : {0.0, 0.2, 0.5, 0.6, 0.9, 1.2, 1.5}) {
    x.t.push_back(t), x.q.push_back(point(t)), x.frame.push_back(frame(t));
    x.v.push_back(Eigen::Vector2d(w, 0)), x.mu.push_back(Eigen::Vector2d(2 * w, 0));
    x.Xi.push_back(Eigen::Matrix2d::Constant(1.5 - t));
  }
  const std::vector<double> times{0.1, 0.33, 0.55, 1.0, 1.49};
  for (cartan::Method method : {cartan::Method::Shooting, cartan::Method::Collocation}) {
    const auto d = general::dense_output(sphere, x, method, times);
    for (std::size_t j = 0; j < times.size(); ++j) {
      EXPECT_NEAR_MATRIX(d.q[j], point(times[j]), 1e-15) << to_string(method);
      EXPECT_NEAR_MATRIX(d.frame[j], frame(times[j]), 1e-15) << to_string(method);
      EXPECT_NEAR_MATRIX(d.v[j], Eigen::Vector2d(w, 0), 1e-14) << to_string(method);
    }
    const auto nodes = general::dense_output(sphere, x, method, x.t);
    for (std::size_t k = 0; k < x.t.size(); ++k) {
      EXPECT_EQ(nodes.q[k], x.q[k]);
      EXPECT_EQ(nodes.frame[k], x.frame[k]);
      EXPECT_EQ(nodes.Xi[k], x.Xi[k]);
    }
  }
  // Xi = (T - t) ones: linear, and its derivative -v mu^T is not that of the data, so only the
  // discrete schemes' linear interpolant reproduces it.
  EXPECT_NEAR_MATRIX(general::dense_output(sphere, x, cartan::Method::Shooting, {0.33}).Xi[0],
                     Eigen::Matrix2d::Constant(1.5 - 0.33), 1e-15);
  expect_invalid([&] { (void)general::dense_output(sphere, x, cartan::Method::Shooting, {1.6}); },
                 {"t = 1.6", "outside [0, T] = [0, 1.5]"});
}

}  // namespace
}  // namespace cartan::testing
