// The one check of a sampled trajectory (principle/samples.hpp), as both kernels use it: the same
// rules and the same words for a Lie-group trajectory (a guess, a result to verify) and a
// manifold's (validate_trajectory), and for the quantities along either.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cartan/groups/so3.hpp"
#include "cartan/kernels/lie_group/along.hpp"
#include "cartan/kernels/lie_group/trajectory.hpp"
#include "cartan/kernels/manifold/along.hpp"
#include "cartan/kernels/manifold/scheme.hpp"
#include "cartan/principle/samples.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Samples, OneRuleEachWithItsWords) {
  const std::vector<Eigen::Vector2d> a{Eigen::Vector2d(0, 1), Eigen::Vector2d(2, 3), Eigen::Vector2d(4, 5)};
  const std::vector<Eigen::Vector2d> b{Eigen::Vector2d(0, 1), Eigen::Vector2d(kNaN, 3), Eigen::Vector2d(4, 5)};
  const std::vector<double> t{0, 0.5, 1};
  EXPECT_TRUE(require_samples(t, 1, {sample_column("a", a)}, {}, "w", "x"));
  expect_invalid([&] { require_samples({0}, 1, {sample_column("a", std::vector<Eigen::Vector2d>{a[0]})}, {}, "w", "x"); },
                 "w: x.t.size() = 1 must be at least 2");
  expect_invalid([&] { require_samples(t, 1, {sample_column("a", a), sample_column("b", b), sample_column("c", a), sample_column("d", std::vector<Eigen::Vector2d>{})}, {}, "w", "x"); },
                 "w: x = (3 times) needs a, b, c and d at every time");
  expect_invalid([&] { require_samples(t, 1, {sample_column("a", a), sample_column("b", b)}, {}, "w", "x"); },
                 {"w: x.b (row 1) = ", "must be finite"});
  expect_invalid([&] { require_samples({0, 0.5, 0.9}, 1, {sample_column("a", a)}, {}, "w", "x"); },
                 "w: x.t = [0, 0.9] must run from 0 to T = 1");
  expect_invalid([&] { require_samples({0, 0.5, 0.5}, 1, {sample_column("a", a)}, {}, "w", "x"); },
                 "w: x.t[2] = 0.5 must be greater than the time before it");
  // Asked only whether they are finite: a non-finite entry or time is an answer, not an error.
  const SampleRules lenient{.min_times = 0, .check_times = false, .require_finite = false};
  EXPECT_FALSE(require_samples(t, 1, {sample_column("b", b)}, lenient, "w", "x"));
  EXPECT_FALSE(require_samples({0, kNaN, 1}, 1, {sample_column("a", a)}, lenient, "w", "x"));
  EXPECT_TRUE(require_samples({}, 1, {sample_column("a", std::vector<Eigen::Vector2d>{})}, lenient, "w", "x"));
}

// The same fault in a trajectory of either kernel is told in the same words (before: "entry 1
// must be finite" on a manifold, "trajectory.v (row 1) = ..." on a group).
TEST(Samples, BothKernelsTellTheSameFaultAlike) {
  transported::TransportedTrajectory<groups::SO3> lie;
  general::GeneralTrajectory<manifolds::Sphere> sphere;
  for (double t : {0.0, 0.5, 1.0}) {
    lie.t.push_back(t), lie.g.push_back(groups::SO3::identity()), lie.v.push_back(Eigen::Vector3d(1, 0, 0));
    lie.mu.push_back(Eigen::Vector3d(1, 0, 0)), lie.xi.push_back(Eigen::Vector3d::Zero());
    sphere.t.push_back(t), sphere.q.push_back(Eigen::Vector3d(1, 0, 0)), sphere.frame.push_back(manifolds::Sphere::Frame::Zero());
    sphere.v.push_back(Eigen::Vector2d(1, 0)), sphere.mu.push_back(Eigen::Vector2d(1, 0)), sphere.Xi.push_back(Eigen::Matrix2d::Zero());
  }
  const general::ErasedProblem<manifolds::Sphere> problem{
      manifolds::Sphere{},
      general::ErasedLagrangian<manifolds::Sphere>(general::KineticPotential<manifolds::Sphere>(Eigen::Matrix2d::Identity())),
      1.0, 2, Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), std::nullopt};
  lie.validate(1.0, "w", true, 1e-12);
  general::validate_trajectory(problem, sphere, "w", "trajectory");
  lie.v[1].x() = kNaN;
  sphere.v[1].x() = kNaN;
  expect_invalid([&] { lie.validate(1.0, "w", true, 1e-12); }, {"w: trajectory.v (row 1) = ", "must be finite"});
  expect_invalid([&] { general::validate_trajectory(problem, sphere, "w", "trajectory"); },
                 {"w: trajectory.v (row 1) = ", "must be finite"});
  lie.g[2](0, 0) = kNaN;  // a point is checked as every other column (before: not at all on a group)
  lie.v[1].x() = 1;
  expect_invalid([&] { lie.validate(1.0, "w", true, 1e-12); }, {"w: trajectory.g (row 2) = ", "must be finite"});
  lie.mu.pop_back();
  sphere.mu.pop_back();
  expect_invalid([&] { lie.validate(1.0, "w", true, 1e-12); }, "w: trajectory = (3 times) needs g, v, mu and xi at every time");
  expect_invalid([&] { general::validate_trajectory(problem, sphere, "w", "trajectory"); },
                 "w: trajectory = (3 times) needs q, frame, v, mu and Xi at every time");
  // Along a solution, sizes only: a non-finite sample makes NaNs, not an error.
  EXPECT_TRUE(std::isnan(transported::along_transport(0.5, lie).u[0].x()));
  lie.v.pop_back();
  sphere.q.pop_back();
  expect_invalid([&] { transported::along_transport(0.5, lie); },
                 "along_solution: trajectory = (3 times) needs g and v at every time");
  expect_invalid([&] { general::along_general(problem, sphere); },
                 "along_general: trajectory = (3 times) needs q and v at every time");
}

}  // namespace
}  // namespace cartan::testing
