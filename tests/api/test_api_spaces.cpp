// The particle on every space of the library's catalogue (cartan/api/spaces.hpp) through the api's
// one ManifoldProblem: checked against closed forms (the projectile in R^n, the free particle in a
// constant-coefficient R^n), against the group model's solve of the same problem, against the
// frame-independence of an isotropic Lagrangian, and through the result file (the one writer and
// reader) and the library's verifier. Bad input is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>
#include <vector>
#include <nlohmann/json.hpp>

#include "cartan/api/result_file.hpp"
#include "cartan/api/solve.hpp"
#include "cartan/api/spaces.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/models/catalogue.hpp"
#include "test_support.hpp"

namespace cartan::api {
namespace {

using connections::ConnectionKind;

/// Options of the second-order scheme.
SolveOptions second_order() {
  SolveOptions o;
  o.order = SchemeOrder::Second;
  return o;
}

/// The result written by the library's writer and read back by its reader (what `cartan verify`
/// and Python's cartan.load read), then verified against the problem the file describes.
ResultRecord round_trip(const ManifoldProblem& problem, const Result& r) {
  const ResultRecord written{on_manifold(problem), kDefaultTol, r};
  const ResultRecord read = read_solution(nlohmann::json::parse(result_text(written)), "test");
  EXPECT_TRUE(read.on_manifold());
  const auto& p = std::get<ManifoldProblem>(read.problem);
  const auto& q = std::get<ManifoldProblem>(written.problem);
  EXPECT_EQ(p.manifold, q.manifold);
  EXPECT_EQ(p.connection, q.connection);
  EXPECT_EQ(p.mass, q.mass);
  EXPECT_EQ(p.alpha, q.alpha);
  EXPECT_EQ(p.frame0, q.frame0);
  EXPECT_EQ(p.q0, q.q0);
  EXPECT_EQ(p.qT, q.qT);
  EXPECT_EQ(read.result.samples.points, r.samples.points);  // 17 significant digits: exact doubles
  const verify::Report report = verify(p, read.result.samples, read.result.order, read.tol, read.result.status);
  EXPECT_TRUE(report.passed()) << report.text();
  return read;
}

TEST(ApiSpaces, TheCatalogueListsEveryCompiledSpaceOnce) {
  EXPECT_EQ(space_names(), "so3, heisenberg, se2, se3, sphere, hyperbolic-plane, euclidean");
  EXPECT_EQ(find_space("euclidean", "test").dims, (std::vector<int>{2, 3}));
  EXPECT_EQ(find_space("se3", "test").dims, (std::vector<int>{6}));
  testing::expect_invalid([] { (void)find_space("torus", "where"); },
                          {"where: manifold = \"torus\"", "is not one of: so3, heisenberg, se2, se3, sphere"});
  testing::expect_invalid([] { require_connection(find_space("sphere", "w"), ConnectionKind::Coefficients, "w"); },
                          {"connection = coefficients", "is not a connection of sphere (it takes: levi-civita)"});
}

TEST(ApiSpaces, TheProjectileInEuclideanSpaceIsTheParabola) {
  // l = 1/2 v^T A v - G q_3 in flat R^3: A q'' = -G e3, so q(t) = q0 + c t - 1/2 a t^2 with
  // a = G A^-1 e3 and c = (qT - q0)/T + 1/2 a T. Both schemes integrate a constant force exactly
  // (their steps are the midpoint and trapezoidal rules of a linear velocity), so only the
  // shooting's tolerance remains: 1e-9.
  ManifoldProblem p;
  p.manifold = "euclidean";
  p.mass = {2, 1, 0.3, 1, 3, 0, 0.3, 0, 4};
  p.gravity = 9.81;
  p.q0 = {0, 0, 0};
  p.qT = {1, 2, -0.5};
  p.T = 1.5;
  p.N = 60;
  const Result r = solve(p, second_order());
  ASSERT_TRUE(r.converged()) << r.message;
  const Eigen::Matrix3d A = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p.mass.data());
  const Eigen::Vector3d a = A.inverse() * Eigen::Vector3d(0, 0, p.gravity);
  const Eigen::Vector3d q0(p.q0.data()), qT(p.qT.data());
  const Eigen::Vector3d c = (qT - q0) / p.T + 0.5 * a * p.T;
  for (Eigen::Index k = 0; k <= p.N; k += 10) {
    const double t = r.samples.t[k];
    const Eigen::Vector3d q = q0 + c * t - 0.5 * a * t * t;
    EXPECT_NEAR((r.samples.points.row(k).transpose() - q).norm(), 0, 1e-9) << k;
    EXPECT_NEAR((r.samples.v.row(k).transpose() - (c - a * t)).norm(), 0, 1e-9) << k;
  }
  round_trip(p, r);
}

TEST(ApiSpaces, ConstantChristoffelSymbolsBendTheFreeParticleInThePlane) {
  // nabla_{e_1} e_1 = kappa e_2 (alpha[0][0][1] = kappa, every other symbol 0) in R^2, l = 1/2
  // |v|^2: the geodesic equation x'' = 0, y'' = -kappa x'^2 gives x = s t, y = y' t - kappa s^2 t^2
  // / 2 with s = (xT - x0) / T and y' fixed by yT. The transported frame turns (e' = -Gamma(q', e)),
  // so v is not q' here; the path is the closed form (second order: 2e-4 at N = 200, h = 0.005,
  // where kappa s^2 = 1.5 and the O(h^2) constant is about that size).
  ManifoldProblem p;
  p.manifold = "euclidean";
  p.connection = ConnectionKind::Coefficients;
  p.alpha = {0, 1.5, 0, 0, 0, 0, 0, 0};
  p.q0 = {0, 0};
  p.qT = {1, 0.4};
  p.N = 200;
  const Result r = solve(p, second_order());
  ASSERT_TRUE(r.converged()) << r.message;
  const double kappa = 1.5, s = 1, slope = 0.4 + kappa / 2;
  for (Eigen::Index k = 0; k <= p.N; k += 25) {
    const double t = r.samples.t[k];
    EXPECT_NEAR(r.samples.points(k, 0), s * t, 2e-4) << k;
    EXPECT_NEAR(r.samples.points(k, 1), slope * t - kappa * s * s * t * t / 2, 2e-4) << k;
  }
  round_trip(p, r);
}

TEST(ApiSpaces, AGroupWithCartanSchoutenIsTheGroupModelsProblem) {
  // The particle 1/2 v^T I v on SO(3) with the Cartan–Schouten connection is the free rigid body of
  // inertia I: the same solve (the library runs its Lie-group kernel for both), the same answer to
  // the shooting's residual.
  ManifoldProblem on_space;
  on_space.manifold = "so3";
  on_space.connection = ConnectionKind::CartanSchouten;
  on_space.lambda = 0.3;
  on_space.mass = {2, 3, 4};
  on_space.qT = models::element_numbers(groups::SO3::exp(Eigen::Vector3d(0.5, -0.3, 0.8)));
  GroupProblem model;
  model.model = "free-rigid-body";
  model.inertia = {2, 3, 4};
  model.lambda = 0.3;
  model.gT = on_space.qT;
  const Result a = solve(on_space), b = solve(model);
  ASSERT_TRUE(a.converged()) << a.message;
  ASSERT_TRUE(b.converged()) << b.message;
  EXPECT_NEAR((a.samples.points - b.samples.points).cwiseAbs().maxCoeff(), 0, 1e-12);
  EXPECT_NEAR((a.samples.v - b.samples.v).cwiseAbs().maxCoeff(), 0, 1e-12);
  EXPECT_NEAR((a.samples.mu - b.samples.mu).cwiseAbs().maxCoeff(), 0, 1e-12);
  round_trip(on_space, a);
  // Levi-Civita of the metric diag(1, 2, 3) with the particle's own mass: the general kernel.
  ManifoldProblem lc = on_space;
  lc.connection = ConnectionKind::LeviCivita;
  lc.metric = {1, 2, 3};
  const Result c = solve(lc);
  ASSERT_TRUE(c.converged()) << c.message;
  round_trip(lc, c);
}

TEST(ApiSpaces, AnIsotropicParticleDoesNotDependOnTheFrame) {
  // l = 1/2 |v|^2 - G z on the sphere: |v| is the same in every orthonormal frame, so the path is
  // the same whichever frame0 is given; v turns with the frame (v' = R^T v).
  ManifoldProblem p;
  p.gravity = 2;
  p.q0 = {1, 0, 0.2};
  p.qT = {0, 0.6, -0.8};
  p.T = 1.2;
  p.N = 120;
  const Result a = solve(p);
  ASSERT_TRUE(a.converged()) << a.message;
  const ManifoldProblem posed = on_manifold(p);
  ASSERT_EQ(posed.frame0.size(), 6u);
  const Eigen::Matrix<double, 2, 3, Eigen::RowMajor> rows(posed.frame0.data());
  const double angle = 0.7;
  Eigen::Matrix2d rotation;
  rotation << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  const Eigen::Matrix<double, 2, 3, Eigen::RowMajor> turned = rotation.transpose() * rows;  // e'_j = sum_i R_ij e_i
  ManifoldProblem q = p;
  q.frame0.assign(turned.data(), turned.data() + 6);
  const Result b = solve(q);
  ASSERT_TRUE(b.converged()) << b.message;
  // Both converge to the shooting tolerance 1e-10 on the same solution: the paths agree to ~1e-9.
  EXPECT_NEAR((a.samples.points - b.samples.points).cwiseAbs().maxCoeff(), 0, 1e-8);
  EXPECT_NEAR((a.samples.v * rotation - b.samples.v).cwiseAbs().maxCoeff(), 0, 1e-8);
  round_trip(q, b);
  // A frame0 given lifts the default frame's condition: q0 = qT is a problem (the particle's
  // return under gravity).
  q.qT = q.q0;
  EXPECT_NO_THROW(check(q));
}

TEST(ApiSpaces, AntipodalEndpointsNeedAFrameOnlyWhereTheLagrangianSeesIt) {
  // Between antipodal points of S^2 every half great circle is minimal, and the default frame's e1
  // (towards qT) is undefined (docs/general-connections.md#frames). The isotropic particle does
  // not see the frame: solved, a half great circle, |v0| = pi / T (a geodesic is exact in the
  // scheme: constant v, the curvature term vanishing against v; 1e-9 is the shooting tolerance).
  // With A = diag(1, 2) the axes' convention would choose the problem: refused by name, and
  // solved once frame0 is given.
  ManifoldProblem p;
  std::tie(p.q0, p.qT, p.T, p.N) = std::tuple(std::vector<double>{0, 0, 1}, std::vector<double>{0, 0, -1}, 2.0, 50);
  const Result a = solve(p);
  ASSERT_TRUE(a.converged()) << a.message;
  EXPECT_NEAR(a.samples.v.row(0).norm(), std::numbers::pi / p.T, 1e-9);
  p.mass = {1, 2};
  testing::expect_invalid([&] { check(p); }, {"q0/qT = [0, 0, 1] / [0, 0, -1] are antipodal", "give frame0"});
  p.frame0 = {1, 0, 0, 0, 1, 0};
  EXPECT_NO_THROW(check(p));
}

TEST(ApiSpaces, BadInputIsRefusedByName) {
  ManifoldProblem p;
  p.q0 = {1, 0, 0};
  p.qT = {0, 1, 0};
  ManifoldProblem bad = p;
  bad.connection = ConnectionKind::CartanSchouten;
  testing::expect_invalid([&] { check(bad); }, {"connection = cartan-schouten", "not a connection of sphere"});
  bad = p;
  bad.metric = {1, 2};
  testing::expect_invalid([&] { check(bad); }, {"metric = 1,2", "not an option of sphere"});
  bad = p;
  bad.mass = {1, 2, 3, 1};
  testing::expect_invalid([&] { check(bad); }, {"mass = 1,2,3,1", "symmetric positive definite"});
  bad = p;
  bad.frame0 = {1, 0, 0, 0, 1, 0};
  testing::expect_invalid([&] { check(bad); }, {"frame0", "tangent vectors at q0"});
  bad.frame0 = {0, 1, 0};
  testing::expect_invalid([&] { check(bad); }, {"frame0 = 0,1,0", "must have 6 numbers"});
  bad = p;
  bad.model = "python:MyLagrangian";
  testing::expect_invalid([&] { check(bad); }, {"model = \"python:MyLagrangian\"", "solved and verified in Python"});
  ManifoldProblem group;
  group.manifold = "se2";
  group.qT = {1, 0, 0.5, 0, 1, 0, 0, 0, 1};
  group.gravity = 1;
  testing::expect_invalid([&] { check(group); }, {"gravity = 1", "does not apply on se2"});
  group.gravity = 0;
  group.qT = {2, 0, 0.5, 0, 1, 0, 0, 0, 1};
  testing::expect_invalid([&] { check(group); }, {"qT"});
  ManifoldProblem plane;
  plane.manifold = "euclidean";
  plane.q0 = {0, 0, 0, 0};
  plane.qT = {1, 0, 0, 0};
  testing::expect_invalid([&] { check(plane); }, {"q0 = 0,0,0,0", "2 or 3 numbers"});
  plane.q0 = {0, 0};
  plane.qT = {1, 0};
  plane.connection = ConnectionKind::Coefficients;
  plane.alpha = {1, 2};
  testing::expect_invalid([&] { check(plane); }, {"alpha = 1,2", "must have 8 numbers"});
}

}  // namespace
}  // namespace cartan::api
