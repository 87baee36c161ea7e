// Heisenberg-group checks against the closed forms printed in the paper's H3 appendix.
#include "cartan/groups/heisenberg.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

using V3 = Eigen::Vector3d;

TEST(Heisenberg, PaperMultiplicationAndInverse) {
  const V3 g(0.3, -1.1, 2.0), h(-0.7, 0.4, 0.25);
  EXPECT_NEAR_MATRIX(groups::Heisenberg::compose(g, h), V3(0.3 - 0.7, -1.1 + 0.4, 2.0 + 0.25 + 0.3 * 0.4), 1e-15);
  EXPECT_NEAR_MATRIX(groups::Heisenberg::inverse(g), V3(-0.3, 1.1, 0.3 * -1.1 - 2.0), 1e-15);
  EXPECT_NEAR_MATRIX(groups::Heisenberg::identity(), V3::Zero(), 0.0);
}

TEST(Heisenberg, AlgebraStructure) {
  // [E1, E2] = E3, E3 central.
  EXPECT_NEAR_MATRIX(groups::bracket<groups::Heisenberg>(V3::UnitX(), V3::UnitY()), V3::UnitZ(), 0.0);
  EXPECT_NEAR_MATRIX(groups::bracket<groups::Heisenberg>(V3::UnitX(), V3::UnitZ()), V3::Zero(), 0.0);
  EXPECT_NEAR_MATRIX(groups::bracket<groups::Heisenberg>(V3::UnitY(), V3::UnitZ()), V3::Zero(), 0.0);
  // (ad-dual-Heis): ad*_u eta = (-eta3 u2, eta3 u1, 0).
  const V3 u(0.2, -0.9, 1.7), eta(1.5, -0.3, 0.8);
  EXPECT_NEAR_MATRIX(groups::coad<groups::Heisenberg>(u, eta), V3(-eta[2] * u[1], eta[2] * u[0], 0), 1e-15);
  // Two-step nilpotent: ad_u ad_w = 0.
  EXPECT_NEAR_MATRIX(groups::Heisenberg::ad(u) * groups::Heisenberg::ad(eta), Eigen::Matrix3d::Zero(), 0.0);
}

TEST(Heisenberg, ReducedVelocityAlongCurve) {
  // (reduced-v-Heis): for g(t) = (a, b, c)(t), g^{-1} g' = (a', b', c' - a b').
  auto curve = [](double t) { return V3(std::sin(t), t * t, std::cos(3 * t)); };
  const double t = 0.7, h = 1e-6;
  const V3 g = curve(t);
  const V3 gdot = (curve(t + h) - curve(t - h)) / (2 * h);
  const V3 u = groups::Heisenberg::left_trivialise(g, gdot);
  EXPECT_NEAR_MATRIX(u, V3(gdot[0], gdot[1], gdot[2] - g[0] * gdot[1]), 1e-15);
  // and through the matrix representation: g^{-1} g' as a matrix.
  const Eigen::Matrix3d m = groups::Heisenberg::matrix(g).inverse() *
                            (groups::Heisenberg::matrix(curve(t + h)) - groups::Heisenberg::matrix(curve(t - h))) / (2 * h);
  EXPECT_NEAR_MATRIX(groups::Heisenberg::hat(u), m, 1e-9);
}

TEST(Heisenberg, DualLeftTranslation) {
  // d(L_g)_e^* eta = (eta1, eta2 + a eta3, eta3) (paper, "Duality").
  const V3 g(0.6, -0.2, 1.3), eta(0.4, 1.1, -2.0);
  EXPECT_NEAR_MATRIX(groups::left_trivialise_covector<groups::Heisenberg>(g, eta), V3(eta[0], eta[1] + g[0] * eta[2], eta[2]), 1e-15);
}

TEST(Heisenberg, ValidateRejectsNonFinite) {
  EXPECT_THROW(groups::Heisenberg::validate(V3(0, std::nan(""), 0), "gT"), std::invalid_argument);
  EXPECT_NO_THROW(groups::Heisenberg::validate(V3(1e300, -2, 0), "gT"));
}

}  // namespace
}  // namespace cartan::testing
