// The api's dense output of samples in numbers (cartan/api/erased.hpp), on a group with the
// Lie-group kernel's samples and on the sphere with the general kernel's. The interpolation is the
// kernels' (tested against its convergence orders in tests/kernels/); here the closed forms of one
// step: at a node the sample itself, between two nodes of a discrete scheme the one-parameter
// subgroup (on SO(3)) or the great circle (on S^2) through both, v and mu linear in s.
#include <gtest/gtest.h>

#include <vector>

#include "cartan/api/erased.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "test_support.hpp"

namespace cartan::api {
namespace {

Eigen::Matrix3d rotation_of_row(const Table& rows, Eigen::Index k) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rows.row(k).eval().data());
}

Result free_body_solution() {
  GroupProblem p;
  p.inertia = {2, 3, 4};
  p.N = 40;
  const Eigen::Matrix3d gT = groups::SO3::exp(Eigen::Vector3d(0.5, -0.3, 0.8));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) p.gT.push_back(gT(i, j));
  }
  return solve(p);
}

TEST(ApiDense, OnAGroupANodeIsItsSampleAndAStepIsTheSubgroupThroughBothNodes) {
  const Result r = free_body_solution();
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.lie_kernel);
  const Samples& x = r.samples;
  const int k = 17;
  const double h = x.t(k + 1) - x.t(k), s = 0.3;
  const Samples d = dense<groups::SO3>(0.5, x, r.method, {x.t(k), x.t(k) + s * h}, "test");
  ASSERT_EQ(d.t.size(), 2);
  // At the node: the sample's own numbers, copied.
  EXPECT_EQ(d.points.row(0), x.points.row(k));
  EXPECT_EQ(d.v.row(0), x.v.row(k));
  EXPECT_EQ(d.aux.row(0), x.aux.row(k));
  EXPECT_EQ(d.frames.size(), 0);
  // Between: g_k exp(s log(g_k^-1 g_k+1)) (a few roundoffs of exp and log), v, mu, xi linear.
  const Eigen::Matrix3d gk = rotation_of_row(x.points, k);
  const Eigen::Matrix3d expected = gk * groups::SO3::exp(s * groups::SO3::log(gk.transpose() * rotation_of_row(x.points, k + 1)));
  EXPECT_NEAR((rotation_of_row(d.points, 1) - expected).cwiseAbs().maxCoeff(), 0, 1e-14);
  EXPECT_NEAR((d.v.row(1) - ((1 - s) * x.v.row(k) + s * x.v.row(k + 1))).cwiseAbs().maxCoeff(), 0, 1e-14);
  EXPECT_NEAR((d.mu.row(1) - ((1 - s) * x.mu.row(k) + s * x.mu.row(k + 1))).cwiseAbs().maxCoeff(), 0, 1e-14);
  EXPECT_NEAR((d.aux.row(1) - ((1 - s) * x.aux.row(k) + s * x.aux.row(k + 1))).cwiseAbs().maxCoeff(), 0, 1e-14);
}

TEST(ApiDense, OnTheSphereAStepIsTheGreatCircleAndTheFrameStaysOrthonormalAndTangent) {
  ManifoldProblem p;
  p.q0 = {1, 0, 0.2};
  p.qT = {0, 1, -0.4};
  p.mass = {1, 2};
  p.N = 30;
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  const Samples& x = r.samples;
  ASSERT_EQ(x.frames.rows(), x.t.size());
  ASSERT_EQ(x.frames.cols(), 6);  // the 3 x 2 frame, row-major
  const int k = 11;
  const double tm = (x.t(k) + x.t(k + 1)) / 2;
  const Samples d = dense(manifolds::Sphere{}, x, r.method, {x.t(k), tm}, "test");
  EXPECT_EQ(d.points.row(0), x.points.row(k));
  EXPECT_EQ(d.frames.row(0), x.frames.row(k));
  // The midpoint of the great-circle arc between two nodes: (q_k + q_k+1) / |q_k + q_k+1|.
  const Eigen::RowVector3d mid = (x.points.row(k) + x.points.row(k + 1)).normalized();
  EXPECT_NEAR((d.points.row(1) - mid).norm(), 0, 1e-15);
  const Eigen::Matrix<double, 3, 2> frame = Eigen::Map<const Eigen::Matrix<double, 3, 2, Eigen::RowMajor>>(d.frames.row(1).eval().data());
  EXPECT_NEAR((frame.transpose() * frame - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 0, 1e-15);
  EXPECT_NEAR((mid * frame).cwiseAbs().maxCoeff(), 0, 1e-15);
  EXPECT_NEAR((d.v.row(1) - (x.v.row(k) + x.v.row(k + 1)) / 2).cwiseAbs().maxCoeff(), 0, 1e-15);
}

TEST(ApiDense, SamplesOfAnotherShapeOrATimeOutsideAreRefusedByName) {
  const Result r = free_body_solution();
  ASSERT_TRUE(r.converged()) << r.message;
  Samples wrong = r.samples;
  wrong.aux.conservativeResize(Eigen::NoChange, 2);
  testing::expect_invalid([&] { (void)dense<groups::SO3>(0.5, wrong, r.method, {0.5}, "here"); }, {"here", "samples.aux", "3 numbers"});
  testing::expect_invalid([&] { (void)dense<groups::SO3>(0.5, r.samples, r.method, {1.5}, "here"); }, {"here", "1.5"});
  ManifoldProblem p;
  p.q0 = {1, 0, 0};
  p.qT = {0, 1, 0};
  const Result on_sphere = solve(p);
  ASSERT_TRUE(on_sphere.converged()) << on_sphere.message;
  Samples frameless = on_sphere.samples;
  frameless.frames.resize(0, 0);
  testing::expect_invalid([&] { (void)dense(manifolds::Sphere{}, frameless, on_sphere.method, {0.5}, "here"); }, {"here", "samples.frames"});
}

}  // namespace
}  // namespace cartan::api
