// Invariant connections and the Cartan–Schouten family, typed over the closed-form groups and one
// generic matrix group (groups/all_groups.hpp).
#include <gtest/gtest-spi.h>

#include "cartan/testing/connection_identities.hpp"
#include "test_support.hpp"
#include "groups/all_groups.hpp"

namespace cartan::testing {
namespace {

template <class G>
class ConnectionTest : public ::testing::Test {};
TYPED_TEST_SUITE(ConnectionTest, GroupsWithOneGeneric);

constexpr double kLambdas[] = {0.0, 0.25, 0.5, 1.0, 1.7, -0.3};

// The general formulas (cur-tor-left and the right versions with their sign changes) applied
// to the CS bilinear maps (CS-conn, CS-conn-right) reproduce (tor-cur-lie-alg).
TYPED_TEST(ConnectionTest, CartanSchoutenTorsionAndCurvature) {
  using G = TypeParam;
  std::mt19937 rng(kSeed);
  for (double lambda : kLambdas) {
    for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
      const auto conn = connections::cartan_schouten<G>(lambda, side);
      EXPECT_TRUE(conn.is_cartan());
      for (int trial = 0; trial < 5; ++trial) {
        const auto u = random_tangent<G>(rng), v = random_tangent<G>(rng), w = random_tangent<G>(rng);
        EXPECT_NEAR_MATRIX(conn.torsion(v, w), connections::cartan_schouten_torsion<G>(lambda, v, w), 1e-13)
            << "lambda " << lambda << " side " << to_string(side);
        EXPECT_NEAR_MATRIX(conn.curvature(u, v, w), connections::cartan_schouten_curvature<G>(lambda, u, v, w), 1e-13)
            << "lambda " << lambda << " side " << to_string(side);
      }
    }
  }
}

TYPED_TEST(ConnectionTest, SpecialParameters) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 1);
  for (int trial = 0; trial < 10; ++trial) {
    const auto u = random_tangent<G>(rng), v = random_tangent<G>(rng), w = random_tangent<G>(rng);
    for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
      // lambda = 0 and 1 are flat, with torsion -[.,.] and +[.,.] (paper's remark, (i)).
      EXPECT_LE(connections::cartan_schouten<G>(0.0, side).curvature(u, v, w).norm(), 1e-14);
      EXPECT_LE(connections::cartan_schouten<G>(1.0, side).curvature(u, v, w).norm(), 1e-14);
      EXPECT_NEAR_MATRIX(connections::cartan_schouten<G>(0.0, side).torsion(v, w), -groups::bracket<G>(v, w), 1e-14);
      EXPECT_NEAR_MATRIX(connections::cartan_schouten<G>(1.0, side).torsion(v, w), groups::bracket<G>(v, w), 1e-14);
      // lambda = 1/2 is torsion-free with R = -1/4 [[u,v],w] (remark, (ii)).
      const auto half = connections::cartan_schouten<G>(0.5, side);
      EXPECT_LE(half.torsion(v, w).norm(), 1e-14);
      EXPECT_NEAR_MATRIX(half.curvature(u, v, w), -0.25 * groups::bracket<G>(groups::bracket<G>(u, v), w), 1e-14);
    }
  }
}

// (eq:cov-curve-left-dual) is the dual of (eq:cov-curve-left): for any trivialised covector
// alpha(t) and vector W(t) along a curve, d/dt <alpha, W> = <D alpha/dt, W> + <alpha, D W/dt>
// (the connection terms cancel only if nabla* is the adjoint of nabla). Random non-Cartan maps,
// both sides; the identity is exact, so 1e-12 bounds the rounding of O(10) sums.
TYPED_TEST(ConnectionTest, DualCovariantDerivativeSatisfiesLeibniz) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 7);
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    for (int trial = 0; trial < 5; ++trial) {
      const auto conn = random_connection<G>(side, rng);
      const auto u = random_tangent<G>(rng), w = random_tangent<G>(rng), dw = random_tangent<G>(rng);
      const auto alpha = random_tangent<G>(rng), dalpha = random_tangent<G>(rng);
      const double product_rule = dalpha.dot(w) + alpha.dot(dw);
      const double covariant = conn.covariant_derivative_dual(u, alpha, dalpha).dot(w) +
                               alpha.dot(conn.covariant_derivative(u, w, dw));
      EXPECT_NEAR(covariant, product_rule, 1e-12) << to_string(side);
    }
  }
}

// The first Bianchi identity holds for arbitrary (non-Cartan) bilinear maps on both sides: an
// independent check of the general torsion and curvature formulas and their right-side signs.
TYPED_TEST(ConnectionTest, BianchiIdentityForRandomConnections) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 2);
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    for (int trial = 0; trial < 5; ++trial) {
      const auto conn = random_connection<G>(side, rng);
      const auto u = random_tangent<G>(rng), v = random_tangent<G>(rng), w = random_tangent<G>(rng);
      EXPECT_LE(bianchi_defect<G>(conn, u, v, w).norm(), 1e-12) << to_string(side);
    }
  }
}

// The installed helper (cartan/testing/connection_identities.hpp) passes on every Cartan–Schouten
// and random connection, both sides.
TYPED_TEST(ConnectionTest, InstalledIdentitiesHold) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 12);
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    for (double lambda : kLambdas) expect_connection_identities<G>(connections::cartan_schouten<G>(lambda, side));
    expect_connection_identities<G>(random_connection<G>(side, rng));
  }
}

/// A user's connection class whose curvature drops the term -nabla_[u,v] w: the installed helper
/// must report the curvature formula and the Bianchi identity (a random, non-Cartan map, for which
/// cyc nabla_[u,v] w does not vanish by Jacobi as it does for lambda ad), and nothing about the torsion.
struct CurvatureWithoutBracketTerm {
  static connections::InvariantConnection<groups::SO3> make() {
    std::mt19937 rng(kSeed + 13);
    return random_connection<groups::SO3>(groups::Side::Left, rng);
  }
  connections::InvariantConnection<groups::SO3> c = make();
  groups::Side side() const { return c.side(); }
  Eigen::Vector3d nabla(const Eigen::Vector3d& u, const Eigen::Vector3d& w) const { return c.nabla(u, w); }
  Eigen::Vector3d torsion(const Eigen::Vector3d& v, const Eigen::Vector3d& w) const { return c.torsion(v, w); }
  Eigen::Vector3d curvature(const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& w) const {
    return c.nabla(u, c.nabla(v, w)) - c.nabla(v, c.nabla(u, w));
  }
};

TEST(InstalledConnectionIdentities, ReportAWrongCurvature) {
  ::testing::TestPartResultArray failures;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    expect_connection_identities<groups::SO3>(CurvatureWithoutBracketTerm{});
  }
  int curvature = 0, bianchi = 0, torsion = 0;
  for (int i = 0; i < failures.size(); ++i) {
    const std::string message = failures.GetTestPartResult(i).message();
    curvature += message.find("curvature formula") != std::string::npos;
    bianchi += message.find("first Bianchi identity") != std::string::npos;
    torsion += message.find("torsion") != std::string::npos;
  }
  EXPECT_EQ(curvature, 10);  // every trial: the dropped term is generically nonzero
  EXPECT_GT(bianchi, 0);
  EXPECT_EQ(torsion, 0);
}

// Bi-invariance (CS-conn-right): the left description lambda ad and the right description
// (lambda - 1) ad give the same covariant derivative of arbitrary vector fields. Tolerance:
// central differences with h = 1e-5 on O(1) fields, error ~1e-10 each; 1e-8 is safe.
TYPED_TEST(ConnectionTest, CartanSchoutenIsBiInvariant) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 3);
  const SmoothField<G> v_field(rng), w_field(rng);
  for (double lambda : kLambdas) {
    const auto left = connections::cartan_schouten<G>(lambda, groups::Side::Left);
    const auto right = connections::cartan_schouten<G>(lambda, groups::Side::Right);
    for (int trial = 0; trial < 4; ++trial) {
      const auto g = random_element<G>(rng);
      const auto from_left = covariant_derivative_of_fields<G>(left, v_field, w_field, g);
      const auto from_right = covariant_derivative_of_fields<G>(right, v_field, w_field, g);
      EXPECT_NEAR_MATRIX(from_left, from_right, 1e-8) << "lambda " << lambda;
    }
  }
  // A non-Cartan-Schouten map is not bi-invariant in this way on a non-abelian group: the same
  // check fails for the left map lambda ad paired with a wrong right map (lambda) ad.
  const auto left = connections::cartan_schouten<G>(0.3, groups::Side::Left);
  const auto wrong_right = connections::cartan_schouten<G>(1.3, groups::Side::Right);
  double worst = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const auto g = random_element<G>(rng);
    worst = std::max(worst, max_abs_diff(covariant_derivative_of_fields<G>(left, v_field, w_field, g),
                                         covariant_derivative_of_fields<G>(wrong_right, v_field, w_field, g)));
  }
  EXPECT_GT(worst, 1e-3);
}

TEST(HeisenbergConnection, CurvatureVanishesForEveryLambda) {
  std::mt19937 rng(kSeed);
  for (double lambda : kLambdas) {
    for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
      const auto conn = connections::cartan_schouten<groups::Heisenberg>(lambda, side);
      for (int trial = 0; trial < 5; ++trial) {
        const auto u = random_tangent<groups::Heisenberg>(rng), v = random_tangent<groups::Heisenberg>(rng),
                   w = random_tangent<groups::Heisenberg>(rng);
        EXPECT_EQ(conn.curvature(u, v, w).norm(), 0.0);
      }
    }
  }
}

TEST(InvariantConnection, ConstructionFromTableAndBilinearMap) {
  using C = connections::InvariantConnection<groups::SO3>;
  // nabla_u w = u x w + 2 (u . w) e1 as a user map: not skew, so not a Cartan connection.
  auto f = [](const Eigen::Vector3d& u, const Eigen::Vector3d& w) -> Eigen::Vector3d {
    return u.cross(w) + 2 * u.dot(w) * Eigen::Vector3d::UnitX();
  };
  const C from_map = C::from_bilinear(groups::Side::Left, f);
  EXPECT_FALSE(from_map.is_cartan());
  Eigen::MatrixXd table(3, 9);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) table.col(3 * i + j) = f(Eigen::Vector3d::Unit(i), Eigen::Vector3d::Unit(j));
  }
  const C from_table = C::from_table(groups::Side::Left, table);
  const Eigen::Vector3d u(0.3, -0.2, 0.9), w(1.1, 0.4, -0.6);
  EXPECT_NEAR_MATRIX(from_map.nabla(u, w), f(u, w), 1e-15);
  EXPECT_NEAR_MATRIX(from_table.nabla(u, w), f(u, w), 1e-15);
  EXPECT_NEAR_MATRIX(from_map.nabla_operator_first(w) * u, f(u, w), 1e-15);
  const Eigen::Vector3d alpha(0.5, 2.0, -1.0);
  EXPECT_NEAR(from_map.nabla_dual(u, alpha).dot(w), alpha.dot(f(u, w)), 1e-15);
}

TEST(InvariantConnection, RejectsBadInput) {
  using C = connections::InvariantConnection<groups::SO3>;
  try {
    C::from_table(groups::Side::Left, Eigen::MatrixXd::Zero(3, 8));
    ADD_FAILURE() << "wrong shape accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has shape 3x8, expected 3x9"), std::string::npos) << e.what();
  }
  Eigen::MatrixXd nan_table = Eigen::MatrixXd::Zero(3, 9);
  nan_table(1, 4) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(C::from_table(groups::Side::Right, nan_table), std::invalid_argument);
  auto not_bilinear = [](const Eigen::Vector3d& u, const Eigen::Vector3d& w) -> Eigen::Vector3d {
    return u.cross(w) + Eigen::Vector3d::Constant(u.squaredNorm() * w.norm());
  };
  try {
    C::from_bilinear(groups::Side::Left, not_bilinear);
    ADD_FAILURE() << "non-bilinear map accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not bilinear"), std::string::npos) << e.what();
  }
  EXPECT_THROW(connections::cartan_schouten<groups::SO3>(std::nan("")), std::invalid_argument);
  const Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();
  expect_invalid([&] { connections::cartan_schouten_torsion<groups::SO3>(INFINITY, e1, e2); }, "cartan_schouten_torsion: lambda = inf");
  expect_invalid([&] { connections::cartan_schouten_curvature<groups::SO3>(std::nan(""), e1, e2, e1); }, "cartan_schouten_curvature: lambda");
}

}  // namespace
}  // namespace cartan::testing
