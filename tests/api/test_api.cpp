// The library's api (cartan/api/solve.hpp): a problem by names and numbers, the kernel chosen by
// the library, one Result. Checked against the closed forms and identities the paper gives, and
// against the library's own verifier; bad input is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "cartan/api/solve.hpp"
#include "cartan/groups/so3.hpp"
#include "test_support.hpp"

namespace cartan::api {
namespace {

/// A rotation's 9 numbers, row-major.
std::vector<double> rotation_numbers(const Eigen::Vector3d& v) {
  const Eigen::Matrix3d r = groups::SO3::exp(v);
  std::vector<double> out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.push_back(r(i, j));
  }
  return out;
}

GroupProblem free_body(connections::ConnectionKind connection) {
  GroupProblem p;
  p.group = "so3";
  p.model = "free-rigid-body";
  p.inertia = {2, 3, 4};
  p.connection = connection;
  p.T = 1;
  p.N = 100;
  p.gT = rotation_numbers({0.5, -0.3, 0.8});
  return p;
}

TEST(Api, CartanSchoutenRunsTheLieGroupKernelAndItsResultVerifies) {
  const GroupProblem p = free_body(connections::ConnectionKind::CartanSchouten);
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_TRUE(r.lie_kernel);
  ASSERT_EQ(r.samples.t.size(), p.N + 1);
  EXPECT_EQ(r.samples.points.cols(), 9);
  EXPECT_EQ(r.samples.aux.cols(), 3);  // xi in g*
  EXPECT_TRUE(std::isfinite(r.action));
  // The last node is gT: the shooting residual is below tol = 1e-10 (radians), so 1e-9 per entry.
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(r.samples.points(p.N, i), p.gT[static_cast<std::size_t>(i)], 1e-9);
  const verify::Report report = verify(p, r.samples, r.order, cartan::kDefaultTol, r.status);
  EXPECT_TRUE(report.passed()) << report.text();
}

TEST(Api, LeviCivitaOfTheBiInvariantMetricIsCartanSchoutenAtOneHalf) {
  // The paper's remark on lambda = 1/2: on SO(3) the bi-invariant metric's Levi-Civita
  // connection is the symmetric Cartan–Schouten one (alpha = 1/2 [., .]). The library solves the
  // first with the general kernel (frame and Xi) and the second with the Lie-group kernel (xi):
  // both take the same discrete steps (piecewise geodesics, the same transport exp(-h/2 ad u)),
  // so their trajectories agree to the shooting's residual (|r| ~ 1e-14), not only to O(h).
  GroupProblem lc = free_body(connections::ConnectionKind::LeviCivita);
  lc.metric = {1, 1, 1};
  GroupProblem cs = free_body(connections::ConnectionKind::CartanSchouten);
  cs.lambda = 0.5;
  const Result a = solve(lc), b = solve(cs);
  ASSERT_TRUE(a.converged()) << a.message;
  ASSERT_TRUE(b.converged()) << b.message;
  EXPECT_FALSE(a.lie_kernel);
  EXPECT_EQ(a.samples.aux.cols(), 9);  // Xi, n^2 numbers row-major
  // The general kernel's action along the samples is the Lie-group kernel's S_h of the same steps.
  EXPECT_NEAR(a.action, b.action, 1e-12 * std::abs(b.action));
  EXPECT_NEAR((a.samples.v - b.samples.v).cwiseAbs().maxCoeff(), 0, 1e-12);
  EXPECT_NEAR((a.samples.points - b.samples.points).cwiseAbs().maxCoeff(), 0, 1e-12);
  const verify::Report report = verify(lc, a.samples, a.order, cartan::kDefaultTol, a.status);
  EXPECT_TRUE(report.passed()) << report.text();
}

TEST(Api, TheFreeParticleOnTheSphereFollowsTheGreatCircleAtConstantSpeed) {
  // l = 1/2 |v|^2 without gravity: a geodesic, the great circle from q0 to qT travelled at the
  // constant speed theta / T; v is its transported velocity in the frame e1 (towards qT), e2.
  ManifoldProblem p;
  p.q0 = {1, 0, 0};
  p.qT = {0, 2, 0};  // normalised by the library
  p.T = 2;
  p.N = 50;
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.frame0.has_value());
  EXPECT_NEAR(((*r.frame0) - (Eigen::Matrix<double, 2, 3>() << 0, 1, 0, 0, 0, 1).finished()).cwiseAbs().maxCoeff(), 0, 1e-15);
  const double speed = std::numbers::pi / 2 / p.T;
  // Piecewise geodesic steps along a geodesic are exact: only the shooting's tolerance remains.
  EXPECT_NEAR((r.samples.v.col(0).array() - speed).abs().maxCoeff(), 0, 1e-9);
  EXPECT_NEAR(r.samples.v.col(1).cwiseAbs().maxCoeff(), 0, 1e-9);
  EXPECT_NEAR((r.samples.points.row(p.N) - Eigen::RowVector3d(0, 1, 0)).norm(), 0, 1e-9);
  const verify::Report report = verify(p, r.samples, r.order, cartan::kDefaultTol, r.status);
  EXPECT_TRUE(report.passed()) << report.text();
}

TEST(Api, TheFreeParticleOnTheHyperbolicPlaneFollowsTheGeodesicAtConstantSpeed) {
  // On H^2 (the sheet z^2 - x^2 - y^2 = 1) the geodesic from the vertex q0 = (0, 0, 1) to
  // qT = (sinh d, 0, cosh d) is q(t) = (sinh(d t/T), 0, cosh(d t/T)), travelled at speed d / T
  // along e1 = (1, 0, 0), with e2 = J (q0 x e1) = (0, 1, 0). qT is given off the sheet (scaled by
  // 3) and moved onto it.
  const double d = 1.3;
  ManifoldProblem p;
  p.manifold = "hyperbolic-plane";
  p.q0 = {0, 0, 1};
  p.qT = {3 * std::sinh(d), 0, 3 * std::cosh(d)};
  p.T = 2;
  p.N = 40;
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_TRUE(r.frame0.has_value());
  EXPECT_NEAR(((*r.frame0) - (Eigen::Matrix<double, 2, 3>() << 1, 0, 0, 0, 1, 0).finished()).cwiseAbs().maxCoeff(), 0, 1e-15);
  // The pieces are geodesics, exact along a geodesic: only the shooting's tolerance remains.
  EXPECT_NEAR((r.samples.v.col(0).array() - d / p.T).abs().maxCoeff(), 0, 1e-9);
  EXPECT_NEAR(r.samples.v.col(1).cwiseAbs().maxCoeff(), 0, 1e-9);
  for (int k = 0; k <= p.N; k += 8) {
    const double s = d * r.samples.t[k] / p.T;
    EXPECT_NEAR((r.samples.points.row(k) - Eigen::RowVector3d(std::sinh(s), 0, std::cosh(s))).norm(), 0, 1e-9) << k;
  }
  const verify::Report report = verify(p, r.samples, r.order, cartan::kDefaultTol, r.status);
  EXPECT_TRUE(report.passed()) << report.text();
  EXPECT_NEAR(on_manifold(p).qT[2], std::cosh(d), 1e-15);
  Guess three;
  three.v0 = {1, 2, 3};
  testing::expect_invalid([&] { (void)on_manifold(p, three); }, {"v0 = 1,2,3", "must have 2"});
  ManifoldProblem outside = p;
  outside.qT = {2, 0, 1};  // z^2 < x^2 + y^2: outside the cone
  testing::expect_invalid([&] { check(outside); }, {"qT = 2,0,1", "hyperbolic plane"});
  outside.manifold = "torus";
  testing::expect_invalid([&] { check(outside); }, {"manifold = \"torus\"", "sphere, hyperbolic-plane"});
}

TEST(Api, ADivergingIterateIsAFailedStatusNotAFaultOfTheModel) {
  // The particle on the sphere with gravity at a long horizon: shooting from the geodesic guess
  // sends an iterate's velocity to NaN inside a step. A non-finite Hessian at a non-finite
  // velocity is the solver's business (a failed sweep), not a ModelError blaming the Lagrangian:
  // every method returns a result, and a result that says converged verifies.
  ManifoldProblem p;
  p.mass = {1, 2.5};
  p.gravity = 3;
  p.q0 = {1, 0, 0.2};
  p.qT = {0, 0.6, -0.8};
  p.T = 8;
  p.N = 200;
  for (const auto& [method, continuation] : {std::pair{Method::Auto, Continuation::None},
                                            std::pair{Method::Shooting, Continuation::None},
                                            std::pair{Method::Shooting, Continuation::T}}) {
    SolveOptions options;
    options.method = method;
    options.continuation = continuation;
    Result r;
    ASSERT_NO_THROW(r = solve(p, options)) << to_string(method) << " " << to_string(continuation);
    EXPECT_FALSE(r.message.empty());
    if (r.converged()) {
      const verify::Report report = verify(p, r.samples, r.order, cartan::kDefaultTol, r.status);
      EXPECT_TRUE(report.passed()) << report.text();
    }
  }
}

TEST(Api, VerifyFailsSamplesThatAreNotASolution) {
  const GroupProblem p = free_body(connections::ConnectionKind::CartanSchouten);
  const Result r = solve(p);
  ASSERT_TRUE(r.converged()) << r.message;
  Samples wrong = r.samples;
  wrong.mu *= 1.1;  // mu is no longer dl/dv
  EXPECT_FALSE(verify(p, wrong, r.order, cartan::kDefaultTol, r.status).passed());
  EXPECT_FALSE(verify(p, r.samples, r.order, cartan::kDefaultTol, Status::NotConverged).passed());
}

TEST(Api, CheckRefusesWhatTheProblemTellsWrongButLeavesGroupMembershipToSolve) {
  // check() is what the CLI validates a whole sweep with before solving any point; a gT off the
  // group is refused by solve, so that the sweep reports it as that point's row.
  GroupProblem off_group = free_body(connections::ConnectionKind::CartanSchouten);
  off_group.gT[0] = 2;
  EXPECT_NO_THROW(check(off_group));
  testing::expect_invalid([&] { (void)solve(off_group); }, {"gT", "not orthogonal"});
  GroupProblem lc = free_body(connections::ConnectionKind::LeviCivita);
  lc.metric = {1, -2, 3};
  testing::expect_invalid([&] { check(lc); }, {"metric = 1,-2,3", "symmetric positive definite"});
  lc.metric = {1, 2};
  testing::expect_invalid([&] { check(lc); }, {"metric = 1,2", "must have 3 numbers (the diagonal) or 9"});
  lc.metric.clear();  // the inertia
  EXPECT_NO_THROW(check(lc));
  ManifoldProblem p;
  p.q0 = {1, 0, 0};
  p.qT = {std::nan(""), 1, 0};
  testing::expect_invalid([&] { check(p); }, {"qT", "non-finite"});
}

TEST(Api, BadInputIsRefusedByName) {
  using testing::expect_invalid;
  using connections::ConnectionKind;
  const GroupProblem good = free_body(ConnectionKind::CartanSchouten);
  const auto with = [&](auto change) {
    GroupProblem p = good;
    change(p);
    return p;
  };
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.group = "so4"; })); }, {"group", "so4"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.model = "pendulum"; })); }, {"model", "pendulum"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.inertia = {1, 2}; })); }, {"inertia = 1,2", "must have 3 numbers (the diagonal) or 9"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.inertia = {1, -2, 3}; })); }, "inertia");
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.gT.clear(); })); }, {"gT", "required"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.gT[0] = 2; })); }, {"gT", "not orthogonal"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.g0 = {1, 0, 0}; })); }, {"g0", "must have 9"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.metric = {1, 1, 1}; })); }, {"metric", "levi-civita only"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.connection = ConnectionKind::Coefficients; })); },
                 {"alpha", "must have 27"});
  const auto guess = [](std::vector<double> v0, std::vector<double> xi0) {
    Guess g;
    g.v0 = std::move(v0);
    g.xi0 = std::move(xi0);
    return g;
  };
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.connection = ConnectionKind::LeviCivita; }), {}, guess({}, {0, 0, 1})); },
                 {"xi0", "Lie-group kernel"});
  expect_invalid([&] { (void)solve(good, {}, guess({1, 2}, {})); }, {"v0", "must have 3"});
  expect_invalid([&] { (void)solve(with([](GroupProblem& p) { p.N = 0; })); }, "N");
  ManifoldProblem antipodal;
  antipodal.q0 = {0, 0, 1};
  antipodal.qT = {0, 0, -3};
  antipodal.mass = {1, 2};  // anisotropic: the default frame decides the problem (test_api_spaces.cpp)
  expect_invalid([&] { (void)solve(antipodal); }, {"q0/qT", "antipodal"});
  ManifoldProblem massless = antipodal;
  massless.qT = {0, 1, 0};
  massless.mass = {1, 0};
  expect_invalid([&] { (void)solve(massless); }, {"mass", "positive"});
  Samples empty;
  empty.t = Eigen::VectorXd::LinSpaced(3, 0, 1);
  expect_invalid([&] { (void)verify(good, empty, 1, 1e-10); }, {"samples.points", "3 rows"});
}

}  // namespace
}  // namespace cartan::api
