// The api's doors for problems given as objects (cartan/api/erased.hpp): verify and along of
// samples in numbers, on a group (the Lie-group kernel's samples) and on the sphere (the general
// kernel's). Checked against what the solve itself reports (its action, its verdict through the
// names door) and against the problem: another Lagrangian or another frame fails.
#include <gtest/gtest.h>

#include <cmath>

#include "cartan/api/erased.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "test_support.hpp"

namespace cartan::api {
namespace {

const Eigen::Vector3d kInertia(2, 3, 4);

mechanics::RigidBody rigid_body(const Eigen::Vector3d& diagonal) {
  return mechanics::RigidBody(Eigen::Matrix3d(diagonal.asDiagonal()));
}

GroupProblem free_body() {
  GroupProblem p;
  p.inertia = {kInertia(0), kInertia(1), kInertia(2)};
  p.N = 40;
  const Eigen::Matrix3d gT = groups::SO3::exp(Eigen::Vector3d(0.5, -0.3, 0.8));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) p.gT.push_back(gT(i, j));
  }
  return p;
}

GroupObjectProblem<groups::SO3> as_object(const GroupProblem& p, const Eigen::Vector3d& inertia) {
  return {mechanics::ErasedLagrangian<groups::SO3>(rigid_body(inertia)), p.lambda, p.T, p.N,
          groups::SO3::identity(),
          Eigen::Matrix3d(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p.gT.data()))};
}

TEST(ApiObjects, AGroupResultVerifiesAsItsObjectProblemAndFailsAsAnother) {
  const GroupProblem p = free_body();
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  const verify::Report by_objects = verify<groups::SO3>(as_object(p, kInertia), r.samples, r.order, kDefaultTol, r.status, "test");
  EXPECT_TRUE(by_objects.passed()) << by_objects.text();
  // The names door runs the same verifier on the same problem: the same figures, bit for bit.
  const verify::Report by_names = verify(p, r.samples, r.order, kDefaultTol, r.status);
  ASSERT_EQ(by_objects.checks.size(), by_names.checks.size());
  for (std::size_t i = 0; i < by_names.checks.size(); ++i) EXPECT_EQ(by_objects.checks[i].figure, by_names.checks[i].figure) << i;
  // Another inertia is another Lagrangian: its Legendre map disagrees with the samples' mu.
  EXPECT_FALSE(verify<groups::SO3>(as_object(p, Eigen::Vector3d(2, 3, 5)), r.samples, r.order, kDefaultTol, r.status, "test").passed());
}

TEST(ApiObjects, AlongAGroupResultEndsAtTheSolvesActionAndStartsAtTheIdentity) {
  const GroupProblem p = free_body();
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  const mechanics::ErasedLagrangian<groups::SO3> lagrangian{rigid_body(kInertia)};
  const Along a = along<groups::SO3>(&lagrangian, p.lambda, r.samples, "test");
  ASSERT_EQ(a.frames.rows(), r.samples.t.size());
  ASSERT_EQ(a.cumulative_action.size(), r.samples.t.size());
  // S_h summed step by step against the solve's own S_h: the same terms, summed in another order.
  EXPECT_NEAR(a.cumulative_action(a.cumulative_action.size() - 1), r.action, 1e-13 * std::abs(r.action));
  EXPECT_EQ(a.cumulative_action(0), 0);
  // P_0 = I (eq:disc-body-v at k = 0), so u_0 = v_0.
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  EXPECT_EQ(a.frames.row(0), Eigen::RowVectorXd::Map(identity.data(), 9));
  EXPECT_NEAR((a.u.row(0) - r.samples.v.row(0)).cwiseAbs().maxCoeff(), 0, 1e-15);
  // Without a Lagrangian: the transport only, the same P.
  const Along transport = along<groups::SO3>(nullptr, p.lambda, r.samples, "test");
  EXPECT_EQ(transport.frames, a.frames);
  EXPECT_EQ(transport.energy.size(), 0);
}

ManifoldProblem on_sphere() {
  ManifoldProblem p;
  p.q0 = {1, 0, 0.2};
  p.qT = {0, 1, -0.4};
  p.mass = {1, 2};
  p.N = 30;
  return p;
}

TEST(ApiObjects, OnAManifoldTheFrameAtQ0ComesFromTheSamplesAndMatters) {
  ManifoldProblem p = on_sphere();
  // A frame at q0 other than the default (its e1 towards qT): the quadric's default rotated by 0.7 rad.
  const Result plain = solve(p);
  ASSERT_TRUE(plain.converged()) << plain.message;
  const Eigen::Matrix<double, 2, 3> e = *plain.frame0;
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Eigen::Matrix<double, 2, 3> rotated = (Eigen::Matrix2d() << c, s, -s, c).finished() * e;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 3; ++j) p.frame0.push_back(rotated(i, j));
  }
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  const Eigen::Vector3d q0 = Eigen::Vector3d(1, 0, 0.2).normalized(), qT = Eigen::Vector3d(0, 1, -0.4).normalized();
  const ManifoldObjectProblem<manifolds::Sphere> problem{
      manifolds::Sphere{}, general::erased_particle<manifolds::Sphere>(Eigen::Matrix2d(Eigen::Vector2d(1, 2).asDiagonal())), p.T, p.N, q0, qT,
      std::nullopt};
  const verify::Report with_frames = verify(problem, r.samples, r.order, kDefaultTol, r.status, "test");
  EXPECT_TRUE(with_frames.passed()) << with_frames.text();
  // Without frames the problem's default frame is taken, in which the samples' v is not the
  // solution's: an anisotropic mass sees the rotation.
  Samples frameless = r.samples;
  frameless.frames.resize(0, 0);
  EXPECT_FALSE(verify(problem, frameless, r.order, kDefaultTol, r.status, "test").passed());
  // along: the frames the samples carry, or rebuilt from frame0 where they carry none.
  ManifoldObjectProblem<manifolds::Sphere> with_frame0 = problem;
  with_frame0.frame0 = rotated.transpose();
  const Along sampled = along(with_frame0, r.samples, "test"), rebuilt = along(with_frame0, frameless, "test");
  // Rebuilt by the same steps' transport the solve used: the same frames to a few roundoffs a step.
  EXPECT_NEAR((sampled.frames - rebuilt.frames).cwiseAbs().maxCoeff(), 0, 1e-13);
  EXPECT_NEAR(sampled.cumulative_action(p.N), r.action, 1e-13 * std::abs(r.action));
}

TEST(ApiObjects, AGroupSolveByTheModelOrBehindTheErasedLagrangianIsOneSolveWithItsAlong) {
  const GroupProblem p = free_body();
  const GroupObjectProblem<groups::SO3> erased = as_object(p, kInertia);
  const transported::TransportedProblem<groups::SO3, mechanics::RigidBody> typed{rigid_body(kInertia), p.lambda, p.T,
                                                                               p.N, erased.g0, erased.gT};
  const Result by_model = solve(typed, {}, {}, {.along = true}, "test");
  const Result by_erased = solve(erased, {}, {}, {.along = true}, "test");
  ASSERT_TRUE(by_model.converged()) << by_model.message;
  ASSERT_TRUE(by_erased.converged()) << by_erased.message;
  // The same member functions evaluated, one through a virtual call: the same iterates.
  EXPECT_NEAR((by_model.samples.points - by_erased.samples.points).cwiseAbs().maxCoeff(), 0, 1e-15);
  EXPECT_NEAR((by_model.v0 - by_erased.v0).cwiseAbs().maxCoeff(), 0, 1e-15);
  ASSERT_EQ(by_model.aux0.size(), 3);  // xi0
  ASSERT_TRUE(by_model.along.has_value());
  // What the solve carries along its samples is api::along of them.
  const mechanics::ErasedLagrangian<groups::SO3> lagrangian{rigid_body(kInertia)};
  const Along again = along<groups::SO3>(&lagrangian, p.lambda, by_model.samples, "test");
  EXPECT_EQ(by_model.along->frames, again.frames);
  EXPECT_EQ(by_model.along->cumulative_action, again.cumulative_action);
  EXPECT_FALSE(solve(erased, {}, {}, {}, "test").along.has_value());
  // Started at its own v0 and xi0, shooting has at most one step left to take.
  Guess start;
  start.v0.assign(by_model.v0.data(), by_model.v0.data() + 3);
  start.xi0.assign(by_model.aux0.data(), by_model.aux0.data() + 3);
  EXPECT_LE(solve(typed, {}, start, {}, "test").inner_iterations, 1);
  Guess from_samples;
  from_samples.trajectory = by_model.samples;
  from_samples.trajectory->mu.resize(0, 0);  // a guess needs no mu
  EXPECT_LE(solve(typed, {}, from_samples, {}, "test").inner_iterations, 1);
}

TEST(ApiObjects, AGuessOfAnotherSizeOrOfTheOtherKernelIsRefusedByName) {
  const GroupProblem p = free_body();
  const GroupObjectProblem<groups::SO3> erased = as_object(p, kInertia);
  Guess short_v0;
  short_v0.v0 = {1, 2};
  testing::expect_invalid([&] { (void)solve(erased, {}, short_v0, {}, "here"); }, {"here", "v0", "must have 3 numbers"});
  Guess Xi0;
  Xi0.Xi0.assign(9, 0);
  testing::expect_invalid([&] { validate(erased, {}, Xi0, "here"); }, {"here", "Xi0", "general kernel"});
  const ManifoldObjectProblem<manifolds::Sphere> on_sphere{manifolds::Sphere{},
                                                           general::erased_particle<manifolds::Sphere>(Eigen::Matrix2d::Identity()),
                                                           1, 20, Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), std::nullopt};
  Guess xi0;
  xi0.xi0 = {0, 0};
  testing::expect_invalid([&] { validate(on_sphere, {}, xi0, "here"); }, {"here", "xi0", "Lie-group kernel"});
  Guess frameless;
  frameless.trajectory = Samples{};
  frameless.trajectory->t = Eigen::VectorXd::LinSpaced(3, 0, 1);
  testing::expect_invalid([&] { validate(on_sphere, {}, frameless, "here"); }, {"here: guess", "samples.points"});
}

TEST(ApiObjects, AFailedResultWithoutSamplesFailsItsConvergedCheckAlone) {
  const GroupProblem p = free_body();
  const Samples none;
  const verify::Report report = verify<groups::SO3>(as_object(p, kInertia), none, 1, kDefaultTol, Status::MaxIterations, "test");
  EXPECT_FALSE(report.passed());
  ASSERT_FALSE(report.checks.empty());
  EXPECT_EQ(report.checks.front().name, "converged");
  Samples wrong;
  wrong.t = Eigen::VectorXd::LinSpaced(3, 0, 1);
  testing::expect_invalid([&] { (void)verify<groups::SO3>(as_object(p, kInertia), wrong, 1, kDefaultTol, Status::Converged, "here"); },
                 {"here", "samples.points"});
}

}  // namespace
}  // namespace cartan::api
