#pragma once
// Reusable checks of the Lie group concept (STYLE.md practice 5), installed for users who write
// their own group (docs/user-guide.md, "Checking your own model"), as Ceres ships its manifold
// invariants. GoogleTest expectations; the group's own formulas are compared with independent
// references: the matrix representation G::matrix, Eigen's matrix exponential of G::hat, and
// central differences.
//
//   #include <cartan/testing/group_axioms.hpp>
//   TEST(MyGroup, IsALieGroup) { cartan::testing::expect_lie_group<MyGroup>(); }
//
// Each check runs at the identity, at a point 1e-8 from it and at 20 seeded random points with
// coordinates in [-1, 1] (sample_tangents). Tolerances are absolute, for elements of entries of
// size <= e^2 (rounding of a handful of flops: 1e-13 to 1e-12; differences: 1e-9 to 1e-8, see
// each function), so a group whose matrices have entries far above 1 needs its own scaling.
//   expect_group_axioms            compose = matrix product, associativity, identity, inverse
//   expect_exp_log                 exp = matrix exponential of hat, log inverts exp, vee inverts hat
//   expect_adjoint                 Ad_g v = vee(g hat(v) g^-1), Ad a homomorphism, Ad_{exp u} = exp(ad_u)
//   expect_ad_and_coad             ad_u v = vee([hat u, hat v]), ad = d Ad, Jacobi, ad* = ad^T
//   expect_translations            left/right translations and trivialisations, of vectors and covectors
//   expect_left_jacobian_is_the_series  groups::left_jacobian against sum ad^k / (k+1)!
//   expect_exp_jacobians_are_the_derivatives  left and right Jacobians of exp by central
//                                  differences, and their inverses
//   expect_lie_group               all of the above
// Needs GoogleTest (link GTest::gtest); the library never includes cartan/testing/.

#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "cartan/groups/exp_jacobian.hpp"
#include "cartan/testing/support.hpp"

namespace cartan::testing {

/// Test points for a group: the identity, a point 1e-8 away, and seeded random points.
template <groups::LieGroup G>
std::vector<groups::TangentOf<G>> sample_tangents(double scale = 1.0, int count = 20) {
  std::mt19937 rng(kSeed);
  std::vector<groups::TangentOf<G>> out{groups::TangentOf<G>::Zero(), groups::TangentOf<G>::Constant(1e-8)};
  for (int i = 0; i < count; ++i) out.push_back(random_tangent<G>(rng, scale));
  return out;
}

template <groups::LieGroup G>
typename G::MatrixRep matrix_of(const groups::ElementOf<G>& g) {
  return G::matrix(g);
}

// Group axioms, checked through the faithful matrix representation (rounding: 1e-13 for
// entries of size <= e^2 with a handful of flops).
template <groups::LieGroup G>
void expect_group_axioms() {
  const auto points = sample_tangents<G>();
  for (std::size_t i = 0; i + 2 < points.size(); ++i) {
    const auto a = G::exp(points[i]), b = G::exp(points[i + 1]), c = G::exp(points[i + 2]);
    EXPECT_NEAR_MATRIX(G::matrix(G::compose(a, b)), G::matrix(a) * G::matrix(b), 1e-13);
    EXPECT_NEAR_MATRIX(G::matrix(G::compose(G::compose(a, b), c)),
                       G::matrix(G::compose(a, G::compose(b, c))), 1e-13);
    EXPECT_NEAR_MATRIX(G::matrix(G::compose(a, G::identity())), G::matrix(a), 0.0);
    EXPECT_NEAR_MATRIX(G::matrix(G::compose(G::inverse(a), a)), G::matrix(G::identity()), 1e-13);
    EXPECT_NEAR_MATRIX(G::matrix(G::inverse(a)), G::matrix(a).inverse(), 1e-12);
  }
}

// exp against Eigen's matrix exponential of hat(v); exp(log(g)) = g; log(exp(v)) = v inside
// the injectivity radius (|v| <= sqrt(3) here).
template <groups::LieGroup G>
void expect_exp_log() {
  for (const auto& v : sample_tangents<G>()) {
    const typename G::MatrixRep x = G::hat(v);
    EXPECT_NEAR_MATRIX(G::matrix(G::exp(v)), x.exp(), 1e-13);
    EXPECT_NEAR_MATRIX(G::log(G::exp(v)), v, 1e-13);
    const auto g = G::exp(v);
    EXPECT_NEAR_MATRIX(G::matrix(G::exp(G::log(g))), G::matrix(g), 1e-13);
    EXPECT_NEAR_MATRIX(G::vee(G::hat(v)), v, 0.0);
  }
}

// Ad_g v = vee(g hat(v) g^{-1}); Ad is a homomorphism; Ad_{exp u} = exp(ad_u).
template <groups::LieGroup G>
void expect_adjoint() {
  const auto points = sample_tangents<G>();
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const auto g = G::exp(points[i]);
    const auto h = G::exp(points[i + 1]);
    const auto m = G::matrix(g);
    const groups::TangentOf<G> v = points[i + 1];
    EXPECT_NEAR_MATRIX(G::Ad(g) * v, G::vee(m * G::hat(v) * m.inverse()), 1e-12);
    EXPECT_NEAR_MATRIX(G::Ad(G::compose(g, h)), G::Ad(g) * G::Ad(h), 1e-12);
    const groups::AlgebraMatrixOf<G> ad = G::ad(points[i]);
    EXPECT_NEAR_MATRIX(G::Ad(g), ad.exp(), 1e-12);
  }
}

// ad_u v = vee([hat u, hat v]); ad = d/dt Ad(exp(t u)) at t = 0 by central differences
// (step 1e-5: truncation ~|u|^3 h^2 ~ 1e-10, rounding ~1e-16/h ~ 1e-11, so 1e-8 is safe);
// Jacobi identity; ad* is the transpose of ad under the pairing mu . v.
template <groups::LieGroup G>
void expect_ad_and_coad() {
  const auto points = sample_tangents<G>();
  std::mt19937 rng(kSeed + 1);
  for (std::size_t i = 0; i + 2 < points.size(); ++i) {
    const groups::TangentOf<G>& u = points[i];
    const groups::TangentOf<G>& v = points[i + 1];
    const groups::TangentOf<G>& w = points[i + 2];
    const auto hu = G::hat(u), hv = G::hat(v);
    EXPECT_NEAR_MATRIX(G::ad(u) * v, G::vee(hu * hv - hv * hu), 1e-14);
    const double h = 1e-5;
    const groups::AlgebraMatrixOf<G> fd = (G::Ad(G::exp(h * u)) - G::Ad(G::exp(-h * u))) / (2 * h);
    EXPECT_NEAR_MATRIX(fd, G::ad(u), 1e-8);
    const groups::TangentOf<G> jacobi = groups::bracket<G>(u, groups::bracket<G>(v, w)) + groups::bracket<G>(v, groups::bracket<G>(w, u)) +
                                groups::bracket<G>(w, groups::bracket<G>(u, v));
    EXPECT_LE(jacobi.cwiseAbs().maxCoeff(), 1e-14);
    // ad* is the dual of ad under the pairing: <ad*_u mu, w> = <mu, [u, w]>, with the bracket
    // from the matrix commutator (independent of G::ad, of which coad is the transpose).
    const groups::CovectorOf<G> mu = random_tangent<G>(rng);
    const auto hw = G::hat(w);
    EXPECT_NEAR(groups::coad<G>(u, mu).dot(w), mu.dot(G::vee(hu * hw - hw * hu)), 1e-13);
  }
}

// d(L_g)_e v and d(R_g)_e v are the derivatives of e -> g exp(e v) and e -> exp(e v) g
// (central differences, step 1e-6: error ~1e-11); trivialisation inverts translation;
// trivialised covectors satisfy <d(L_g)^* alpha, v> = <alpha, d(L_g) v>.
template <groups::LieGroup G>
void expect_translations() {
  const auto points = sample_tangents<G>();
  std::mt19937 rng(kSeed + 2);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const auto g = G::exp(points[i]);
    const groups::TangentOf<G>& v = points[i + 1];
    const double h = 1e-6;
    const groups::ElementOf<G> left_fd =
        (G::compose(g, G::exp(h * v)) - G::compose(g, G::exp(-h * v))) / (2 * h);
    const groups::ElementOf<G> right_fd =
        (G::compose(G::exp(h * v), g) - G::compose(G::exp(-h * v), g)) / (2 * h);
    EXPECT_NEAR_MATRIX(G::left_translate(g, v), left_fd, 1e-9);
    EXPECT_NEAR_MATRIX(G::right_translate(g, v), right_fd, 1e-9);
    EXPECT_NEAR_MATRIX(G::left_trivialise(g, G::left_translate(g, v)), v, 1e-13);
    EXPECT_NEAR_MATRIX(G::right_trivialise(g, G::right_translate(g, v)), v, 1e-13);
    // g^{-1} (v g) = Ad_{g^{-1}} v
    EXPECT_NEAR_MATRIX(G::left_trivialise(g, G::right_translate(g, v)), G::Ad(G::inverse(g)) * v, 1e-12);
    const groups::ElementOf<G> alpha = G::left_translate(g, random_tangent<G>(rng)) + G::right_translate(g, v);
    EXPECT_NEAR(groups::left_trivialise_covector<G>(g, alpha).dot(v), groups::ambient_pairing<G>(alpha, G::left_translate(g, v)),
                1e-12);
    EXPECT_NEAR(groups::right_trivialise_covector<G>(g, alpha).dot(v),
                groups::ambient_pairing<G>(alpha, G::right_translate(g, v)), 1e-12);
  }
}

// The left Jacobian (a group's closed form, or the generic phi1 of ad) against the series
// sum_k ad_x^k / (k+1)! evaluated independently, by the block exponential of [[ad_x, I], [0, 0]]
// (Pade, accurate to ~1e-15 relative); across the series/closed-form thresholds of the groups
// (1e-4 and 1e-2) and up to |x| = 3. Tolerance 1e-13 (1 + |x|^2): the entries grow like |x|^2
// (SE(3)'s Q block) and each side rounds at a few eps of that. And exp_and_left_jacobian gives
// the same exponential as exp, to the last bit, and the same Jacobian.
template <groups::LieGroup G>
void expect_left_jacobian_is_the_series() {
  std::mt19937 rng(kSeed + 3);
  for (double size : {0.0, 1e-9, 0.99e-4, 1.01e-4, 0.99e-2, 1.01e-2, 0.3, 1.5, 3.0}) {
    const groups::TangentOf<G> x = random_tangent<G>(rng, 1.0).normalized() * size;
    Eigen::Matrix<double, 2 * G::kDim, 2 * G::kDim> block = Eigen::Matrix<double, 2 * G::kDim, 2 * G::kDim>::Zero();
    block.template topLeftCorner<G::kDim, G::kDim>() = G::ad(x);
    block.template topRightCorner<G::kDim, G::kDim>().setIdentity();
    const groups::AlgebraMatrixOf<G> series = block.exp().template topRightCorner<G::kDim, G::kDim>();
    EXPECT_NEAR_MATRIX(groups::left_jacobian<G>(x), series, 1e-13 * (1 + size * size)) << "|x| = " << size;
    const auto [e, j] = groups::exp_and_left_jacobian<G>(x);
    EXPECT_NEAR_MATRIX(G::matrix(e), G::matrix(G::exp(x)), 0.0) << "|x| = " << size;
    EXPECT_NEAR_MATRIX(j, groups::left_jacobian<G>(x), 1e-15 * (1 + size * size)) << "|x| = " << size;
  }
}

// The exponential's Jacobians as derivatives, by central differences (step 1e-5: truncation about
// 1e-10, rounding about 1e-11, scaled by the entries' size 1 + |x|^2): exp(x + e w) =
// exp(e J_l(x) w) exp(x) + O(e^2) and exp(x) exp(e J_r(x) w) + O(e^2); and left_jacobian_inverse,
// right_jacobian_inverse (a group's closed form or the generic inverse) invert them (J is well
// conditioned for |x| <= 2: rounding only). Up to |x| = 2, where log inverts exp near exp(x) on
// every shipped group (rotation angles below pi).
template <groups::LieGroup G>
void expect_exp_jacobians_are_the_derivatives() {
  std::mt19937 rng(kSeed + 4);
  const double e = 1e-5;
  const groups::AlgebraMatrixOf<G> identity = groups::AlgebraMatrixOf<G>::Identity();
  for (double size : {0.0, 1e-3, 0.3, 1.0, 2.0}) {
    const groups::TangentOf<G> x = random_tangent<G>(rng, 1.0).normalized() * size;
    const groups::TangentOf<G> w = random_tangent<G>(rng, 1.0);
    const groups::ElementOf<G> g = G::exp(x), g_inverse = G::inverse(g);
    const groups::ElementOf<G> plus = G::exp(groups::TangentOf<G>(x + e * w));
    const groups::ElementOf<G> minus = G::exp(groups::TangentOf<G>(x - e * w));
    const groups::TangentOf<G> left = (G::log(G::compose(plus, g_inverse)) - G::log(G::compose(minus, g_inverse))) / (2 * e);
    const groups::TangentOf<G> right = (groups::log_between<G>(g, plus) - groups::log_between<G>(g, minus)) / (2 * e);
    const double scale = 1 + size * size;
    EXPECT_NEAR_MATRIX(left, groups::left_jacobian<G>(x) * w, 1e-8 * scale) << "|x| = " << size;
    EXPECT_NEAR_MATRIX(right, groups::right_jacobian<G>(x) * w, 1e-8 * scale) << "|x| = " << size;
    EXPECT_NEAR_MATRIX(groups::left_jacobian_inverse<G>(x) * groups::left_jacobian<G>(x), identity, 1e-12 * scale)
        << "|x| = " << size;
    EXPECT_NEAR_MATRIX(groups::right_jacobian_inverse<G>(x) * groups::right_jacobian<G>(x), identity, 1e-12 * scale)
        << "|x| = " << size;
  }
}

/// Every check above.
template <groups::LieGroup G>
void expect_lie_group() {
  expect_group_axioms<G>();
  expect_exp_log<G>();
  expect_adjoint<G>();
  expect_ad_and_coad<G>();
  expect_translations<G>();
  expect_left_jacobian_is_the_series<G>();
  expect_exp_jacobians_are_the_derivatives<G>();
}

}  // namespace cartan::testing
