// MatrixLieGroup (groups defined by a basis of their algebra) and the closed-form rigid motion
// groups SE(2) and SE(3): structure constants, closed forms against the generic matrix
// exponential/logarithm versions, the SO(3) left Jacobian they rest on, log near angle pi, and
// rejection of invalid bases and non-group matrices.
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>
#include <string_view>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/matrix_group.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/testing/group_axioms.hpp"  // sample_tangents
#include "test_support.hpp"

namespace cartan::testing {
namespace {

using V3 = Eigen::Vector3d;

/// Levi-Civita symbol eps_ijk for indices in {0, 1, 2}.
double levi_civita(int i, int j, int k) { return (i - j) * (j - k) * (k - i) / 2.0; }

// ---------------------------------------------------------------------------------------------
// Structure constants and the projection vee.

TEST(MatrixLieGroup, SO3GenericStructureConstantsAreThoseOfSo3) {
  const auto& c = groups::SO3Generic::structure_constants();  // c[i](k, j) = c_ij^k
  EXPECT_EQ(c[0](2, 1), 1.0);                          // [E1, E2] = E3
  EXPECT_EQ(c[1](0, 2), 1.0);                          // [E2, E3] = E1
  EXPECT_EQ(c[2](1, 0), 1.0);                          // [E3, E1] = E2
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) EXPECT_EQ(c[i](k, j), levi_civita(i, j, k)) << i << j << k;
    }
  }
  EXPECT_NEAR_MATRIX(groups::SO3Generic::gram(), 2 * Eigen::Matrix3d::Identity(), 0.0);
  std::mt19937 rng(kSeed);
  const V3 v = random_vector<V3>(rng, 2.0), w = random_vector<V3>(rng, 2.0);
  EXPECT_NEAR_MATRIX(groups::SO3Generic::hat(v), groups::SO3::hat(v), 0.0);
  EXPECT_NEAR_MATRIX(groups::SO3Generic::hat(v) * w, v.cross(w), 1e-15);
  EXPECT_NEAR_MATRIX(groups::SO3Generic::ad(v), groups::SO3::ad(v), 0.0);
}

// Both vee's are the Frobenius projection onto the algebra, so they agree on any matrix, not
// only on algebra elements.
template <class Closed, class Generic>
void expect_same_projection() {
  using MatrixRep = typename Closed::MatrixRep;
  using Entries = Eigen::Matrix<double, MatrixRep::SizeAtCompileTime, 1>;
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 10; ++trial) {
    const Entries entries = random_vector<Entries>(rng, 3.0);
    const MatrixRep x = Eigen::Map<const MatrixRep>(entries.data());
    EXPECT_NEAR_MATRIX(Closed::vee(x), Generic::vee(x), 1e-15);
  }
}

TEST(MatrixLieGroup, VeeIsTheFrobeniusProjection) {
  expect_same_projection<groups::SO3, groups::SO3Generic>();
  expect_same_projection<groups::SE3, groups::SE3Generic>();
  expect_same_projection<groups::SE2, groups::SE2Generic>();
}

// A basis that is neither orthogonal nor normalised: {E1, E1 + E2, 2 E3} of so(3). vee must
// invert hat through the (non-diagonal) Gram matrix and the structure constants change with it.
struct SkewedSO3Basis {
  static constexpr int kDim = 3;
  static constexpr int kMatrixSize = 3;
  static constexpr std::string_view name() { return "so3-skewed"; }
  static std::array<Eigen::Matrix3d, 3> basis() {
    const auto e = groups::SO3Basis::basis();
    return {e[0], e[0] + e[1], 2 * e[2]};
  }
};

TEST(MatrixLieGroup, NonOrthonormalBasis) {
  using G = groups::MatrixLieGroup<SkewedSO3Basis>;
  // [E1, E1 + E2] = E3 = (1/2)(2 E3), so c_12^3 = 1/2.
  EXPECT_NEAR(G::structure_constants()[0](2, 1), 0.5, 1e-15);
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 10; ++trial) {
    const V3 u = random_vector<V3>(rng, 1.0), v = random_vector<V3>(rng, 1.0);
    EXPECT_NEAR_MATRIX(G::vee(G::hat(v)), v, 1e-15);
    const Eigen::Matrix3d hu = G::hat(u), hv = G::hat(v);
    EXPECT_NEAR_MATRIX(G::ad(u) * v, G::vee(hu * hv - hv * hu), 1e-15);
    // Same group as SO(3): exp agrees with Rodrigues on the same algebra element.
    EXPECT_NEAR_MATRIX(G::exp(v), groups::SO3::exp(groups::SO3::vee(hv)), 1e-15);
  }
}

// A user-defined nilpotent group: the Heisenberg algebra as strictly upper triangular matrices,
// E1 = e_12, E2 = e_23, E3 = e_13 (the Heisenberg class's hat). exp(hat v) is unipotent, so the
// generic log works on a defective matrix (a single Jordan block of eigenvalue 1).
struct HeisenbergBasis {
  static constexpr int kDim = 3;
  static constexpr int kMatrixSize = 3;
  static constexpr std::string_view name() { return "heisenberg-generic"; }
  static std::array<Eigen::Matrix3d, 3> basis() {
    std::array<Eigen::Matrix3d, 3> e;
    for (int i = 0; i < 3; ++i) e[i] = groups::Heisenberg::hat(V3::Unit(i));
    return e;
  }
};

TEST(MatrixLieGroup, UserDefinedHeisenbergGroupMatchesHeisenberg) {
  using G = groups::MatrixLieGroup<HeisenbergBasis>;
  for (const V3& v : sample_tangents<groups::Heisenberg>()) {
    const Eigen::Matrix3d g = groups::Heisenberg::matrix(groups::Heisenberg::exp(v));
    EXPECT_NEAR_MATRIX(G::exp(v), g, 1e-15);
    EXPECT_NEAR_MATRIX(G::log(g), v, 1e-14);
    EXPECT_NEAR_MATRIX(G::Ad(g), groups::Heisenberg::Ad(groups::Heisenberg::exp(v)), 1e-15);
    EXPECT_NEAR_MATRIX(G::ad(v), groups::Heisenberg::ad(v), 0.0);
  }
}

// ---------------------------------------------------------------------------------------------
// Closed forms against the generic matrix-exponential versions.

// At the identity, at 1e-8 and at seeded random points with rotation angles up to
// sqrt(3) * scale. Tolerances: 1e-13 absolute on entries of size <= ~5, i.e. ~100 ulps for
// Eigen's Pade/Schur evaluations (observed: <= 6e-15). ad uses the same +-1 structure constants
// on both sides and is exact.
template <class Closed, class Generic>
void expect_closed_form_matches_generic(double scale) {
  static_assert(Closed::kDim == Generic::kDim);
  for (const auto& v : sample_tangents<Closed>(scale, 40)) {
    EXPECT_NEAR_MATRIX(Closed::hat(v), Generic::hat(v), 0.0);
    const typename Closed::Element g = Closed::exp(v);
    EXPECT_NEAR_MATRIX(g, Generic::exp(v), 1e-13) << "v = " << v.transpose();
    EXPECT_NEAR_MATRIX(Closed::log(g), Generic::log(g), 1e-13) << "v = " << v.transpose();
    EXPECT_NEAR_MATRIX(Closed::Ad(g), Generic::Ad(g), 1e-13) << "v = " << v.transpose();
    EXPECT_NEAR_MATRIX(Closed::ad(v), Generic::ad(v), 0.0) << "v = " << v.transpose();
    EXPECT_NEAR_MATRIX(Closed::inverse(g), Generic::inverse(g), 1e-13);
  }
}

TEST(MatrixLieGroup, SE3ClosedFormMatchesGeneric) {
  expect_closed_form_matches_generic<groups::SE3, groups::SE3Generic>(1.0);
  expect_closed_form_matches_generic<groups::SE3, groups::SE3Generic>(1.7);  // angles up to 2.94
}

TEST(MatrixLieGroup, SE2ClosedFormMatchesGeneric) {
  expect_closed_form_matches_generic<groups::SE2, groups::SE2Generic>(1.0);
  expect_closed_form_matches_generic<groups::SE2, groups::SE2Generic>(3.0);  // |theta| up to 3
}

TEST(MatrixLieGroup, SO3ClosedFormMatchesGeneric) { expect_closed_form_matches_generic<groups::SO3, groups::SO3Generic>(1.0); }

// On both sides of SO3::kSmallAngle, where exp switches from Taylor series to sin/cos: the
// closed forms must stay as accurate as the generic ones (a 1 - cos t evaluated directly there
// once cost SE(3)'s exp 6e-13).
TEST(MatrixLieGroup, ClosedFormsAreAccurateAtTheSeriesThreshold) {
  std::mt19937 rng(kSeed);
  for (double factor : {0.5, 0.999999, 1.000001, 2.0, 10.0}) {
    const double angle = groups::SO3::kSmallAngle * factor;
    const V3 axis = random_vector<V3>(rng, 1.0).normalized();
    groups::SE3::Tangent v;
    v << random_vector<V3>(rng, 2.0), angle * axis;
    EXPECT_NEAR_MATRIX(groups::SE3::exp(v), groups::SE3Generic::exp(v), 1e-15) << "angle " << angle;
    EXPECT_NEAR_MATRIX(groups::SE3::log(groups::SE3::exp(v)), v, 2e-15) << "angle " << angle;
    const V3 w(v[0], v[1], angle);
    EXPECT_NEAR_MATRIX(groups::SE2::exp(w), groups::SE2Generic::exp(w), 1e-15) << "angle " << angle;
    EXPECT_NEAR_MATRIX(groups::SE2::log(groups::SE2::exp(w)), w, 2e-15) << "angle " << angle;
  }
}

// ---------------------------------------------------------------------------------------------
// The SO(3) left Jacobian behind SE(3)'s closed forms.

TEST(SO3, LeftJacobianIsDerivativeOfExp) {
  std::mt19937 rng(kSeed);
  for (double angle : {0.0, 1e-9, 1e-5, 0.3, 1.5, 3.0}) {
    const V3 v = random_vector<V3>(rng, 1.0).normalized() * angle;
    const V3 w = random_vector<V3>(rng, 1.0);
    // d/ds exp(v + s w) at s = 0 = hat(J(v) w) exp(v); central differences, step 1e-6:
    // truncation ~1e-12, rounding ~1e-16 / 1e-6 = 1e-10.
    const double h = 1e-6;
    const Eigen::Matrix3d derivative = (groups::SO3::exp(v + h * w) - groups::SO3::exp(v - h * w)) / (2 * h);
    EXPECT_NEAR_MATRIX(groups::SO3::vee(derivative * groups::SO3::exp(v).transpose()), groups::SO3::left_jacobian(v) * w, 1e-9)
        << "angle " << angle;
  }
}

TEST(SO3, LeftJacobianInverse) {
  std::mt19937 rng(kSeed);
  const double threshold = groups::SO3::kSmallAngle;
  for (double angle : {0.0, 1e-12, 1e-6, threshold * 0.999999, threshold * 1.000001, 1e-2, 1.0, 3.0,
                       std::numbers::pi - 1e-9, std::numbers::pi}) {
    const V3 v = random_vector<V3>(rng, 1.0).normalized() * angle;
    EXPECT_NEAR_MATRIX(groups::SO3::left_jacobian_inverse(v) * groups::SO3::left_jacobian(v), Eigen::Matrix3d::Identity(), 1e-15)
        << "angle " << angle;
  }
}

// ---------------------------------------------------------------------------------------------
// log near rotation angle pi.

// The reference is built in long double from the axis-angle closed forms, independently of
// SE3::exp: R = I + sin t K + (1 - cos t) K^2, translation J(t n) rho with
// J = I + ((1 - cos t)/t) K + ((t - sin t)/t) K^2 (K = hat(n)). The rotation part has the same
// accuracy requirement as SO3's (relative 1e-12); J^{-1} is well conditioned near pi
// (singular values 1 and ~2/pi), so rho inherits it.
TEST(SE3, LogNearPiIsAccurate) {
  using LongMatrix = Eigen::Matrix<long double, 3, 3>;
  std::mt19937 rng(kSeed);
  for (double gap : {1e-3, 1e-6, 1e-9, 3e-12}) {
    for (int trial = 0; trial < 5; ++trial) {
      const V3 n = random_vector<V3>(rng, 1.0).normalized();
      const V3 rho = random_vector<V3>(rng, 2.0);
      const long double t = std::numbers::pi_v<long double> - gap;
      LongMatrix k;
      k << 0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0;
      const LongMatrix r = LongMatrix::Identity() + std::sin(t) * k + (1 - std::cos(t)) * k * k;
      const LongMatrix jacobian =
          LongMatrix::Identity() + (1 - std::cos(t)) / t * k + (t - std::sin(t)) / t * k * k;
      const Eigen::Matrix<long double, 3, 1> translation = jacobian * rho.cast<long double>();
      const groups::SE3::Element g = groups::SE3::from_rotation_translation(r.cast<double>(), translation.cast<double>());

      const groups::SE3::Tangent got = groups::SE3::log(g);
      const V3 omega_expected = n * static_cast<double>(t);
      EXPECT_LE((groups::SE3::omega(got) - omega_expected).norm() / omega_expected.norm(), 1e-12) << "gap " << gap;
      EXPECT_LE((groups::SE3::rho(got) - rho).norm() / rho.norm(), 1e-12) << "gap " << gap;
      EXPECT_NEAR_MATRIX(groups::SE3::exp(got), g, 1e-14) << "gap " << gap;
    }
  }
}

// At exactly pi either logarithm may be returned; each must re-exponentiate to g.
TEST(SE3, LogAtPiReexponentiates) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 5; ++trial) {
    groups::SE3::Tangent v;
    v << random_vector<V3>(rng, 2.0), random_vector<V3>(rng, 1.0).normalized() * std::numbers::pi;
    const groups::SE3::Element g = groups::SE3::exp(v);
    const groups::SE3::Tangent got = groups::SE3::log(g);
    EXPECT_NEAR(groups::SE3::omega(got).norm(), std::numbers::pi, 1e-12);
    EXPECT_NEAR_MATRIX(groups::SE3::exp(got), g, 1e-13);
  }
}

TEST(SE2, LogNearPi) {
  for (double theta : {std::numbers::pi - 1e-6, std::numbers::pi - 1e-12, -std::numbers::pi + 1e-9}) {
    const V3 v(0.7, -1.3, theta);
    EXPECT_NEAR_MATRIX(groups::SE2::log(groups::SE2::exp(v)), v, 1e-14) << "theta " << theta;
  }
  // Exactly pi: theta comes back as +pi and the round trip holds.
  const V3 v(0.7, -1.3, std::numbers::pi);
  EXPECT_NEAR_MATRIX(groups::SE2::exp(groups::SE2::log(groups::SE2::exp(v))), groups::SE2::exp(v), 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Invalid bases.

// {E1, E2} of so(3): [E1, E2] = E3 is not in the span.
struct NotClosedBasis {
  static constexpr int kDim = 2;
  static constexpr int kMatrixSize = 3;
  static constexpr std::string_view name() { return "so3-without-E3"; }
  static std::array<Eigen::Matrix3d, 2> basis() {
    const auto e = groups::SO3Basis::basis();
    return {e[0], e[1]};
  }
};

// Closed (abelian) but E2 = 2 E1.
struct DependentBasis {
  static constexpr int kDim = 2;
  static constexpr int kMatrixSize = 2;
  static constexpr std::string_view name() { return "dependent"; }
  static std::array<Eigen::Matrix2d, 2> basis() {
    const Eigen::Matrix2d e1 = Eigen::Vector2d(1, -1).asDiagonal();
    return {e1, 2 * e1};
  }
};

struct NonFiniteBasis {
  static constexpr int kDim = 1;
  static constexpr int kMatrixSize = 2;
  static constexpr std::string_view name() { return "non-finite"; }
  static std::array<Eigen::Matrix2d, 1> basis() {
    Eigen::Matrix2d e = Eigen::Matrix2d::Zero();
    e(0, 1) = std::nan("");
    return {e};
  }
};

TEST(MatrixLieGroup, RejectsBasisNotClosedUnderTheBracket) {
  using G = groups::MatrixLieGroup<NotClosedBasis>;
  expect_invalid([] { G::check_basis(); },
                 {"MatrixLieGroup<so3-without-E3>", "[E1, E2] = [", "not in the span"});
  // Every use of the basis reports it, not only the first.
  expect_invalid([] { (void)G::structure_constants(); }, {"[E1, E2]"});
  expect_invalid([] { (void)G::exp(Eigen::Vector2d(0.1, 0.2)); }, {"[E1, E2]"});
  expect_invalid([] { G::validate(Eigen::Matrix3d::Identity(), "g"); }, {"[E1, E2]"});
}

TEST(MatrixLieGroup, RejectsLinearlyDependentBasis) {
  expect_invalid([] { groups::MatrixLieGroup<DependentBasis>::check_basis(); },
                 {"MatrixLieGroup<dependent>", "Gram matrix", "[2, 4; 4, 8]",
                                      "not linearly independent"});
}

TEST(MatrixLieGroup, RejectsNonFiniteBasis) {
  expect_invalid([] { groups::MatrixLieGroup<NonFiniteBasis>::check_basis(); },
                 {"MatrixLieGroup<non-finite>", "E1 = [0, nan", "non-finite"});
}

// ---------------------------------------------------------------------------------------------
// validate.

TEST(MatrixLieGroup, ValidateAcceptsGroupElements) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 10; ++trial) {
    const groups::SE3::Element g3 = random_element<groups::SE3>(rng);
    EXPECT_NO_THROW(groups::SE3::validate(g3, "g"));
    EXPECT_NO_THROW(groups::SE3Generic::validate(g3, "g"));
    const groups::SE2::Element g2 = random_element<groups::SE2>(rng);
    EXPECT_NO_THROW(groups::SE2::validate(g2, "g"));
    EXPECT_NO_THROW(groups::SE2Generic::validate(g2, "g"));
    EXPECT_NO_THROW(groups::SO3Generic::validate(random_element<groups::SO3>(rng), "g"));
  }
}

TEST(SE3, ValidateRejectsNonGroupMatrices) {
  const groups::SE3::Element g = groups::SE3::exp((groups::SE3::Tangent() << 1, 2, 3, 0.3, -0.2, 0.1).finished());

  groups::SE3::Element bottom_row = g;
  bottom_row(3, 0) = 0.5;
  expect_invalid([&] { groups::SE3::validate(bottom_row, "g0"); },
                 {"SE3: g0 = [", "0.5, 0, 0, 1]", "bottom row [0.5, 0, 0, 1], not [0, 0, 0, 1]"});
  expect_invalid([&] { groups::SE3Generic::validate(bottom_row, "g0"); },
                 {"MatrixLieGroup<se3-generic>: g0 = [", "0.5, 0, 0, 1]", "not in the group"});

  groups::SE3::Element scaled = g;
  scaled.topLeftCorner<3, 3>() *= 1.01;
  expect_invalid([&] { groups::SE3::validate(scaled, "gT"); },
                 {"SE3: gT = [", "invalid rotation block", "gT rotation block = [", "not orthogonal"});
  expect_invalid([&] { groups::SE3Generic::validate(scaled, "gT"); },
                 {"MatrixLieGroup<se3-generic>: gT = [", "not in the group"});

  groups::SE3::Element reflected = g;
  reflected.row(0) *= -1;
  expect_invalid([&] { groups::SE3::validate(reflected, "g"); }, {"SE3: g = [", "has determinant -", "(a reflection?)"});

  groups::SE3::Element nan = g;
  nan(1, 3) = std::nan("");
  expect_invalid([&] { groups::SE3::validate(nan, "g"); }, {"SE3: g = [", "non-finite"});
  expect_invalid([&] { groups::SE3Generic::validate(nan, "g"); }, {"non-finite"});
}

TEST(SE2, ValidateRejectsNonGroupMatrices) {
  const groups::SE2::Element g = groups::SE2::exp(V3(1.0, -2.0, 0.7));

  groups::SE2::Element bottom_row = g;
  bottom_row(2, 1) = -0.25;
  expect_invalid([&] { groups::SE2::validate(bottom_row, "pose"); },
                 {"SE2: pose = [", "bottom row [0, -0.25, 1], not [0, 0, 1]"});
  expect_invalid([&] { groups::SE2Generic::validate(bottom_row, "pose"); },
                 {"MatrixLieGroup<se2-generic>: pose = [", "not in the group"});

  groups::SE2::Element sheared = g;
  sheared(0, 1) += 0.1;
  expect_invalid([&] { groups::SE2::validate(sheared, "pose"); },
                 {"SE2: pose = [", "invalid rotation block", "not orthogonal"});
  expect_invalid([&] { groups::SE2Generic::validate(sheared, "pose"); }, {"not in the group"});
}

}  // namespace
}  // namespace cartan::testing
