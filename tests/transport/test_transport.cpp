// Ordered exponentials and parallel transport (include/cartan/transport/parallel_transport.hpp): cor-parr,
// parr-tran-Cartan-lambda, rem-simple / para-trans-heis, para-trans-Heis, para-trans-dual-Heis.
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

#include "cartan/connections/cartan_schouten.hpp"
#include "cartan/transport/disc_exp.hpp"
#include "cartan/transport/parallel_transport.hpp"
#include "cartan/testing/connection_identities.hpp"
#include "groups/all_groups.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

constexpr transport::TransportMethod kMethods[] = {transport::TransportMethod::LieEuler, transport::TransportMethod::Magnus2, transport::TransportMethod::Magnus4};

/// A curve with closed-form group values and velocities on any group:
///   g(t) = exp(t a) exp(phi(t) b) exp(psi(t) c),  phi = sin t,  psi = t^2/2,
/// body velocity  u_L = g^{-1} g' = Ad_{exp(-psi c)} (Ad_{exp(-phi b)} a + phi' b) + psi' c,
/// right velocity u_R = g' g^{-1} = Ad_g u_L. It is not a one-parameter subgroup.
template <groups::LieGroup G>
struct KnownCurve {
  groups::TangentOf<G> a, b, c;
  explicit KnownCurve(std::mt19937& rng)
      : a(random_tangent<G>(rng, 0.8)), b(random_tangent<G>(rng, 0.8)), c(random_tangent<G>(rng, 0.8)) {}
  groups::ElementOf<G> operator()(double t) const {
    return G::compose(G::compose(G::exp(groups::TangentOf<G>(t * a)), G::exp(groups::TangentOf<G>(std::sin(t) * b))),
                      G::exp(groups::TangentOf<G>(0.5 * t * t * c)));
  }
  groups::TangentOf<G> body(double t) const {
    const groups::TangentOf<G> inner = G::Ad(G::exp(groups::TangentOf<G>(-std::sin(t) * b))) * a + std::cos(t) * b;
    return G::Ad(G::exp(groups::TangentOf<G>(-0.5 * t * t * c))) * inner + t * c;
  }
  groups::TangentOf<G> spatial(double t) const { return G::Ad((*this)(t)) * body(t); }
  groups::TangentOf<G> velocity(groups::Side side, double t) const { return side == groups::Side::Left ? body(t) : spatial(t); }
};

template <class Vec>
std::vector<Vec> sample(const std::function<Vec(double)>& f, double s, double t, int n, bool midpoints) {
  std::vector<Vec> out;
  const double h = (t - s) / n;
  for (int k = 0; k < (midpoints ? n : n + 1); ++k) out.push_back(f(s + k * h + (midpoints ? 0.5 * h : 0.0)));
  return out;
}

/// A random ambient covector (an Element-shaped array, not necessarily tangent to G).
template <groups::LieGroup G>
groups::ElementOf<G> random_ambient(std::mt19937& rng) {
  using Flat = Eigen::Matrix<double, groups::ElementOf<G>::SizeAtCompileTime, 1>;
  return random_vector<Flat>(rng, 1.0).reshaped(groups::ElementOf<G>::RowsAtCompileTime, groups::ElementOf<G>::ColsAtCompileTime);
}

template <class G>
class TransportTest : public ::testing::Test {};
TYPED_TEST_SUITE(TransportTest, GroupsWithOneGeneric);

// The test curve's velocities are right: compare with central differences of g(t) in ambient
// coordinates (step 1e-5, truncation ~1e-10 on O(1) derivatives; 1e-8 is safe).
TYPED_TEST(TransportTest, KnownCurveVelocities) {
  using G = TypeParam;
  std::mt19937 rng(kSeed);
  const KnownCurve<G> curve(rng);
  for (double t : {0.0, 0.4, 1.3}) {
    const double e = 1e-5;
    const groups::ElementOf<G> gdot = (curve(t + e) - curve(t - e)) / (2 * e);
    EXPECT_NEAR_MATRIX(G::left_trivialise(curve(t), gdot), curve.body(t), 1e-8);
    EXPECT_NEAR_MATRIX(G::right_trivialise(curve(t), gdot), curve.spatial(t), 1e-8);
  }
}

// Paper's remark after tor-cur-lie-alg, (i): lambda = 0 transport is left translation,
// lambda = 1 right translation. Left-trivialised: P = I (lambda = 0; the generator vanishes, so
// every method returns I to rounding) and P(s -> t) = Ad(g(t)^{-1} g(s)) (lambda = 1);
// right-trivialised (CS-conn-right, generator -(lambda - 1) ad): P = I for lambda = 1 and
// P = Ad(g(t) g(s)^{-1}) for lambda = 0. Magnus4 with 64 steps of h = 0.0172 over [0.2, 1.3]:
// the measured error (method error O(h^4)) is <= 9e-10 on every group, so 1e-8.
TYPED_TEST(TransportTest, FlatConnectionsAreLeftAndRightTranslation) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 1);
  const KnownCurve<G> curve(rng);
  const double s = 0.2, t = 1.3;
  const groups::ElementOf<G> gs = curve(s), gt = curve(t);
  const groups::AlgebraMatrixOf<G> identity = groups::AlgebraMatrixOf<G>::Identity();
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    auto u = [&curve, side](double r) { return curve.velocity(side, r); };
    const double trivial_lambda = side == groups::Side::Left ? 0.0 : 1.0;
    for (transport::TransportMethod m : kMethods) {
      EXPECT_NEAR_MATRIX(transport::transport_operator(connections::cartan_schouten<G>(trivial_lambda, side), u, s, t, 16, m), identity, 1e-15);
      EXPECT_NEAR_MATRIX(transport::cartan_schouten_transport<G>(trivial_lambda, side, u, s, t, 16, m), identity, 1e-15);
    }
    const double other_lambda = 1.0 - trivial_lambda;
    const groups::AlgebraMatrixOf<G> expected =
        side == groups::Side::Left ? G::Ad(G::compose(G::inverse(gt), gs)) : G::Ad(G::compose(gt, G::inverse(gs)));
    const auto p = transport::transport_operator(connections::cartan_schouten<G>(other_lambda, side), u, s, t, 64, transport::TransportMethod::Magnus4);
    EXPECT_NEAR_MATRIX(p, expected, 1e-8) << to_string(side);
    // In ambient coordinates: Gamma X = X g(s)^{-1} g(t) (right translation) for lambda = 1.
    const auto p_right_translation =
        side == groups::Side::Left ? p
                           : transport::transport_operator(connections::cartan_schouten<G>(1.0, side), u, s, t, 64, transport::TransportMethod::Magnus4);
    const auto p_left_translation =
        side == groups::Side::Left ? transport::transport_operator(connections::cartan_schouten<G>(0.0, side), u, s, t, 64, transport::TransportMethod::Magnus4)
                           : p;
    for (int trial = 0; trial < 3; ++trial) {
      const groups::ElementOf<G> x = G::left_translate(gs, random_tangent<G>(rng));
      EXPECT_NEAR_MATRIX(transport::transport_tangent<G>(side, p_right_translation, gs, gt, x),
                         G::right_translate(gt, G::right_trivialise(gs, x)), 1e-8);
      EXPECT_NEAR_MATRIX(transport::transport_tangent<G>(side, p_left_translation, gs, gt, x),
                         G::left_translate(gt, G::left_trivialise(gs, x)), 1e-8);
    }
  }
}

// A Cartan–Schouten connection is bi-invariant (CS-conn, CS-conn-right), so its left and right
// descriptions transport ambient vectors identically (parr-tran-Cartan-lambda, both lines).
// Both are Magnus4 approximations with 128 steps of h ~ 0.008 (measured difference <= 4e-10 on
// every group; it is 5e-9 at 64 steps, i.e. O(h^4) method error, not rounding): 1e-8.
TYPED_TEST(TransportTest, CartanSchoutenLeftAndRightDescriptionsAgree) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 2);
  const KnownCurve<G> curve(rng);
  const double s = 1.1, t = 0.1;  // backwards, as well
  for (double lambda : {0.5, 0.3, 1.7}) {
    const auto pl = transport::cartan_schouten_transport<G>(
        lambda, groups::Side::Left, [&](double r) { return curve.body(r); }, s, t, 128, transport::TransportMethod::Magnus4);
    const auto pr = transport::cartan_schouten_transport<G>(
        lambda, groups::Side::Right, [&](double r) { return curve.spatial(r); }, s, t, 128, transport::TransportMethod::Magnus4);
    for (int trial = 0; trial < 3; ++trial) {
      const groups::ElementOf<G> x = G::left_translate(curve(s), random_tangent<G>(rng));
      EXPECT_NEAR_MATRIX(transport::transport_tangent<G>(groups::Side::Left, pl, curve(s), curve(t), x),
                         transport::transport_tangent<G>(groups::Side::Right, pr, curve(s), curve(t), x), 1e-8)
          << "lambda " << lambda;
    }
  }
}

// The fast path P = Ad(Y), Y' = -lambda u Y in G, computes the same Magnus exponents as the
// generic path on -lambda ad_u (ad is a homomorphism, exp(ad w) = Ad(exp w)), so they agree to
// rounding: a few hundred flops per step on entries of size <= ~10 (SE(3)'s Ad grows with the
// translation), 32 steps; 1e-12 relative to max(1, |P|).
TYPED_TEST(TransportTest, CartanSchoutenFastPathMatchesGenericPath) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 3);
  const KnownCurve<G> curve(rng);
  const double s = 0.0, t = 1.2;
  const int n = 32;
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    std::function<groups::TangentOf<G>(double)> u = [&curve, side](double r) { return curve.velocity(side, r); };
    const auto nodes = sample(u, s, t, n, false), mids = sample(u, s, t, n, true);
    for (double lambda : {0.5, 1.7, -0.3}) {
      const auto conn = connections::cartan_schouten<G>(lambda, side);
      for (transport::TransportMethod m : kMethods) {
        const auto generic = transport::transport_operator(conn, u, s, t, n, m);
        const double tol = 1e-12 * std::max(1.0, generic.cwiseAbs().maxCoeff());
        EXPECT_NEAR_MATRIX(transport::cartan_schouten_transport<G>(lambda, side, u, s, t, n, m), generic, tol)
            << to_string(m) << " lambda " << lambda << " " << to_string(side);
        EXPECT_NEAR_MATRIX(transport::cartan_schouten_transport<G>(lambda, side, transport::Samples{nodes, mids, s, t}, m),
                           transport::transport_operator(conn, transport::Samples{nodes, mids, s, t}, m), tol)
            << to_string(m) << " lambda " << lambda;
        const auto fast_nodes = transport::cartan_schouten_transport_nodes<G>(lambda, side, u, s, t, n, m);
        const auto generic_nodes = transport::transport_operator_nodes(conn, u, s, t, n, m);
        ASSERT_EQ(fast_nodes.size(), static_cast<std::size_t>(n + 1));
        ASSERT_EQ(generic_nodes.size(), static_cast<std::size_t>(n + 1));
        for (std::size_t k = 0; k < fast_nodes.size(); ++k) EXPECT_NEAR_MATRIX(fast_nodes[k], generic_nodes[k], tol);
      }
      // The Lie–Euler fast path is (disc-exp) step by step.
      groups::ElementOf<G> y = G::identity();
      const double c = side == groups::Side::Left ? lambda : lambda - 1;
      for (int k = 0; k < n; ++k) y = transport::disc_exp_update<G>(c, (t - s) / n, nodes[k], y);
      const groups::AlgebraMatrixOf<G> p = G::Ad(y);
      EXPECT_NEAR_MATRIX(transport::cartan_schouten_transport<G>(lambda, side, transport::Samples{nodes, {}, s, t}, transport::TransportMethod::LieEuler), p,
                         1e-12 * std::max(1.0, p.cwiseAbs().maxCoeff()));
    }
  }
}

// Dual transport preserves the pairing (eq:parr-left-dual): <Gamma*_s^t alpha, Gamma_s^t X> =
// <alpha, X>, and the pull-back is the adjoint: <Gamma*_t^s beta, X> = <beta, Gamma_s^t X>, for
// a general (non-Cartan-Schouten) connection on both sides, trivialised and ambient. These are
// identities of linear algebra (P^{-T} by an LU solve, ambient covectors by a Gram solve), so
// rounding only: 1e-11 relative to the size of the terms (|P| up to ~20 here).
TYPED_TEST(TransportTest, DualTransportPreservesPairing) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 4);
  const KnownCurve<G> curve(rng);
  const double s = 0.3, t = 1.0;
  const groups::ElementOf<G> gs = curve(s), gt = curve(t);
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    const auto conn = random_connection<G>(side, rng);
    const auto p = transport::transport_operator(
        conn, [&](double r) { return curve.velocity(side, r); }, s, t, 16, transport::TransportMethod::Magnus4);
    const double scale = std::max(1.0, p.cwiseAbs().maxCoeff() * p.inverse().cwiseAbs().maxCoeff());
    for (int trial = 0; trial < 3; ++trial) {
      const groups::TangentOf<G> x = random_tangent<G>(rng);
      const groups::CovectorOf<G> alpha = random_tangent<G>(rng), beta = random_tangent<G>(rng);
      EXPECT_NEAR(transport::transport_covector(p, alpha).dot(transport::transport_vector(p, x)), alpha.dot(x), 1e-11 * scale);
      EXPECT_NEAR(transport::pull_back_covector(p, beta).dot(x), beta.dot(transport::transport_vector(p, x)), 1e-11 * scale);

      // Ambient: a tangent vector X at g(s), arbitrary ambient covectors (not tangent to G on
      // matrix groups: only their tangential part matters).
      const groups::ElementOf<G> xa = groups::translate<G>(side, gs, x);
      const groups::ElementOf<G> alpha_a = random_ambient<G>(rng), beta_a = random_ambient<G>(rng);
      const groups::ElementOf<G> transported = transport::transport_tangent<G>(side, p, gs, gt, xa);
      EXPECT_NEAR(groups::ambient_pairing<G>(transport::transport_ambient_covector<G>(side, p, gs, gt, alpha_a), transported),
                  groups::ambient_pairing<G>(alpha_a, xa), 1e-11 * scale);
      EXPECT_NEAR(groups::ambient_pairing<G>(transport::pull_back_ambient_covector<G>(side, p, gs, gt, beta_a), xa),
                  groups::ambient_pairing<G>(beta_a, transported), 1e-11 * scale);
      // untrivialise_covector inverts trivialise_covector on trivialised covectors.
      EXPECT_NEAR_MATRIX(groups::trivialise_covector<G>(side, gt, groups::untrivialise_covector<G>(side, gt, alpha)), alpha, 1e-12);
    }
  }
}

// Transport backwards is the inverse: P(t -> s) P(s -> t) = I. The symmetric methods (Magnus2,
// Magnus4) give the exact inverse of the discrete forward map (their exponents change sign with
// h and the Gauss points / trapezoid nodes are mirrored), so rounding only: 1e-12 relative to
// |P| |P^{-1}|. Lie–Euler is not symmetric; its defect is O(h) (checked: it halves when the
// steps double, ratio in [1.8, 2.2]). t = s gives I.
TYPED_TEST(TransportTest, BackwardTransportIsTheInverse) {
  using G = TypeParam;
  std::mt19937 rng(kSeed + 5);
  const KnownCurve<G> curve(rng);
  const auto conn = random_connection<G>(groups::Side::Left, rng);
  std::function<groups::TangentOf<G>(double)> u = [&curve](double r) { return curve.body(r); };
  const double s = 0.1, t = 0.9;
  const groups::AlgebraMatrixOf<G> identity = groups::AlgebraMatrixOf<G>::Identity();
  for (transport::TransportMethod m : {transport::TransportMethod::Magnus2, transport::TransportMethod::Magnus4}) {
    const auto forward = transport::transport_operator(conn, u, s, t, 24, m);
    const auto backward = transport::transport_operator(conn, u, t, s, 24, m);
    const double scale = forward.cwiseAbs().maxCoeff() * backward.cwiseAbs().maxCoeff();
    EXPECT_NEAR_MATRIX(backward * forward, identity, 1e-12 * scale) << to_string(m);
    // Sampled: the backward samples are the forward ones in reverse order.
    auto nodes = sample(u, s, t, 24, false), mids = sample(u, s, t, 24, true);
    const auto forward_sampled = transport::transport_operator(conn, transport::Samples{nodes, mids, s, t}, m);
    std::reverse(nodes.begin(), nodes.end());
    std::reverse(mids.begin(), mids.end());
    EXPECT_NEAR_MATRIX(transport::transport_operator(conn, transport::Samples{nodes, mids, t, s}, m) * forward_sampled, identity,
                       1e-12 * scale)
        << to_string(m);
    // The fast path too.
    const auto fast_forward = transport::cartan_schouten_transport<G>(0.7, groups::Side::Left, u, s, t, 24, m);
    const auto fast_backward = transport::cartan_schouten_transport<G>(0.7, groups::Side::Left, u, t, s, 24, m);
    EXPECT_NEAR_MATRIX(fast_backward * fast_forward, identity,
                       1e-12 * fast_forward.cwiseAbs().maxCoeff() * fast_backward.cwiseAbs().maxCoeff());
  }
  auto euler_defect = [&](int n) {
    return max_abs_diff(transport::transport_operator(conn, u, t, s, n, transport::TransportMethod::LieEuler) *
                            transport::transport_operator(conn, u, s, t, n, transport::TransportMethod::LieEuler),
                        identity);
  };
  const double ratio = euler_defect(64) / euler_defect(128);
  EXPECT_GT(ratio, 1.8);
  EXPECT_LT(ratio, 2.2);
  for (transport::TransportMethod m : kMethods) {
    EXPECT_NEAR_MATRIX(transport::transport_operator(conn, u, s, s, 5, m), identity, 0.0);
    EXPECT_NEAR_MATRIX(transport::cartan_schouten_transport<G>(0.5, groups::Side::Left, u, s, s, 5, m), identity, 0.0);
    const auto at_nodes = transport::transport_operator_nodes(conn, u, s, s, 5, m);
    ASSERT_EQ(at_nodes.size(), 6u);
    for (const auto& pk : at_nodes) EXPECT_NEAR_MATRIX(pk, identity, 0.0);
  }
}

// ------------------------------------------------------------------------------------------
// H3: the closed forms of the appendix

using V3 = Eigen::Vector3d;

/// A polynomial curve (a, b, c)(t) whose a and b have the given degree (c is a cubic: it does
/// not enter ad_u, which depends on u1 = a', u2 = b' only (ad-Heis)).
struct PolynomialH3Curve {
  int degree;
  double a(double t) const { return poly(t, {0.3, 1.1, -0.7, 0.4, 0.25}); }
  double b(double t) const { return poly(t, {-0.5, 0.6, 0.9, -0.35, 0.15}); }
  double c(double t) const { return 0.2 - 0.4 * t + 0.8 * t * t - 0.3 * t * t * t; }
  double da(double t) const { return dpoly(t, {0.3, 1.1, -0.7, 0.4, 0.25}); }
  double db(double t) const { return dpoly(t, {-0.5, 0.6, 0.9, -0.35, 0.15}); }
  double dc(double t) const { return -0.4 + 1.6 * t - 0.9 * t * t; }
  V3 g(double t) const { return V3(a(t), b(t), c(t)); }
  /// (reduced-v-Heis): g^{-1} g' = (a', b', c' - a b').
  V3 body(double t) const { return V3(da(t), db(t), dc(t) - a(t) * db(t)); }

  double poly(double t, std::array<double, 5> coef) const {
    double x = 0;
    for (int i = degree; i >= 0; --i) x = x * t + coef[i];
    return x;
  }
  double dpoly(double t, std::array<double, 5> coef) const {
    double x = 0;
    for (int i = degree; i >= 1; --i) x = x * t + i * coef[i];
    return x;
  }
};

// (para-trans-Heis) and (para-trans-dual-Heis) hold to rounding. Why the methods are exact here:
// h3 is two-step nilpotent, ad_u ad_w = 0 (rem-simple), so for the generator A = -lambda ad_u
// every product A(r1) A(r2) vanishes: the Texp series stops at I + int A, each Magnus step has
// exp(Omega) = I + Omega with a vanishing commutator term, and the product of the steps is
// I + sum_k Omega_k. So a method is exact exactly when its quadrature integrates u1 = a', u2 = b'
// exactly: Gauss (Magnus4) for a, b of degree <= 4, midpoint (Magnus2) for degree <= 2, left
// point (LieEuler) for degree <= 1 — with any number of steps (3 here). Tolerance: entries of
// size <= ~10, a few dozen flops: 1e-13.
TEST(HeisenbergTransport, ClosedFormsOfTheAppendix) {
  const std::pair<transport::TransportMethod, int> exact_for[] = {
      {transport::TransportMethod::LieEuler, 1}, {transport::TransportMethod::Magnus2, 2}, {transport::TransportMethod::Magnus4, 4}};
  const double s = -0.4, t = 1.3;
  for (const auto& [method, degree] : exact_for) {
    const PolynomialH3Curve curve{degree};
    const double da = curve.a(t) - curve.a(s), db = curve.b(t) - curve.b(s);
    for (double lambda : {0.0, 0.5, 1.0, 1.7, -0.3}) {
      auto u = [&curve](double r) { return curve.body(r); };
      const auto p = transport::transport_operator(connections::cartan_schouten<groups::Heisenberg>(lambda), u, s, t, 3, method);
      const auto p_fast = transport::cartan_schouten_transport<groups::Heisenberg>(lambda, groups::Side::Left, u, s, t, 3, method);
      // Trivialised: P = I - lambda int ad_u = I + lambda [row 3: (Delta b, -Delta a, 0)].
      Eigen::Matrix3d expected = Eigen::Matrix3d::Identity();
      expected(2, 0) = lambda * db;
      expected(2, 1) = -lambda * da;
      EXPECT_NEAR_MATRIX(p, expected, 1e-13) << to_string(method) << " lambda " << lambda;
      EXPECT_NEAR_MATRIX(p_fast, expected, 1e-13) << to_string(method) << " lambda " << lambda;

      const V3 v(0.7, -1.3, 0.4), eta(1.2, 0.5, -0.9);
      // (para-trans-Heis), in the ambient coordinates (d/da, d/db, d/dc):
      const V3 gamma_v(v[0], v[1], v[2] + (1 - lambda) * da * v[1] + lambda * db * v[0]);
      EXPECT_NEAR_MATRIX(transport::transport_tangent<groups::Heisenberg>(groups::Side::Left, p, curve.g(s), curve.g(t), v), gamma_v, 1e-13)
          << to_string(method) << " lambda " << lambda;
      // (para-trans-dual-Heis), in the ambient dual coordinates (da, db, dc): the pull-back
      // Gamma*(g)_t^s = (Gamma(g)_s^t)^* of a covector at g(t).
      const V3 gamma_star_eta(eta[0] + lambda * eta[2] * db, eta[1] + (1 - lambda) * eta[2] * da, eta[2]);
      EXPECT_NEAR_MATRIX(transport::pull_back_ambient_covector<groups::Heisenberg>(groups::Side::Left, p, curve.g(s), curve.g(t), eta),
                         gamma_star_eta, 1e-13)
          << to_string(method) << " lambda " << lambda;
      // Its inverse is the forward dual transport Gamma*(g)_s^t.
      EXPECT_NEAR_MATRIX(transport::transport_ambient_covector<groups::Heisenberg>(groups::Side::Left, p, curve.g(s), curve.g(t), gamma_star_eta),
                         eta, 1e-13);
    }
  }
  // A degree too high for the quadrature: the method is no longer exact (the check has teeth).
  const PolynomialH3Curve quartic{4};
  const auto p = transport::transport_operator(
      connections::cartan_schouten<groups::Heisenberg>(0.5), [&](double r) { return quartic.body(r); }, s, t, 3, transport::TransportMethod::Magnus2);
  EXPECT_GT(std::abs(p(2, 1) + 0.5 * (quartic.a(t) - quartic.a(s))), 1e-4);
}

// ------------------------------------------------------------------------------------------
// Convergence orders

/// Observed orders log2(e_N / e_2N), log2(e_2N / e_4N) of approx(n) against reference.
template <class Approx, class Reference>
std::array<double, 2> observed_orders(const Approx& approx, const Reference& reference, int n) {
  const double e1 = max_abs_diff(approx(n), reference), e2 = max_abs_diff(approx(2 * n), reference),
               e4 = max_abs_diff(approx(4 * n), reference);
  return {std::log2(e1 / e2), std::log2(e2 / e4)};
}

/// Coarsest step counts N per method, chosen in the asymptotic range with e_4N well above the
/// reference's error and rounding (on SO(3), CS 0.5: Magnus4 e_8 = 1.6e-5 ... e_32 = 6.4e-8).
int coarse_steps(transport::TransportMethod m) {
  switch (m) {
    case transport::TransportMethod::LieEuler:
      return 32;
    case transport::TransportMethod::Magnus2:
      return 16;
    case transport::TransportMethod::Magnus4:
      return 8;
  }
  return 0;
}

void expect_orders(const std::string& what, transport::TransportMethod m, const std::array<double, 2>& orders) {
  std::cout << "[ orders   ] " << what << " " << to_string(m) << ": " << orders[0] << ", " << orders[1] << "\n";
  EXPECT_NEAR(orders[0], order(m), 0.15) << what << " " << to_string(m);
  EXPECT_NEAR(orders[1], order(m), 0.15) << what << " " << to_string(m);
}

// Measured orders 1, 2, 4 by refinement on SO(3) along the smooth non-geodesic body velocity
// u(t) = (sin t, cos 2t, t^2/2) on [0, 2], for the CS connection lambda = 0.5 (generic and fast
// paths) and a general (non-Cartan-Schouten) connection, from u as a function and from samples
// (trapezoid for Magnus2, Simpson + commutator for Magnus4). Reference: Magnus4 with 4096 steps
// (it differs from an 8192-step one by 3e-14, far below the smallest e_4N = 6e-8 compared).
// Tolerance +-0.15 on each observed order (measured: within 0.03 of 1, 2, 4).
TEST(TransportConvergence, OrdersOnSO3) {
  using G = groups::SO3;
  std::function<V3(double)> u = [](double t) { return V3(std::sin(t), std::cos(2 * t), 0.5 * t * t); };
  const double s = 0.0, t = 2.0;
  std::mt19937 rng(kSeed + 6);
  const std::pair<std::string, connections::InvariantConnection<G>> connections[] = {
      {"cartan-schouten(0.5)", connections::cartan_schouten<G>(0.5)}, {"general", random_connection<G>(groups::Side::Left, rng)}};
  for (const auto& entry : connections) {
    const std::string& name = entry.first;  // not a structured binding: lambdas below capture it
    const connections::InvariantConnection<G>& conn = entry.second;
    const auto reference = transport::transport_operator(conn, u, s, t, 4096, transport::TransportMethod::Magnus4);
    for (transport::TransportMethod m : kMethods) {
      const int n = coarse_steps(m);
      expect_orders(name + " function", m,
                    observed_orders([&](int k) { return transport::transport_operator(conn, u, s, t, k, m); }, reference, n));
      expect_orders(name + " samples", m,
                    observed_orders(
                        [&](int k) {
                          return transport::transport_operator(conn, transport::Samples{sample(u, s, t, k, false), sample(u, s, t, k, true), s, t}, m);
                        },
                        reference, n));
      if (name == "general") continue;
      expect_orders(name + " fast path", m,
                    observed_orders([&](int k) { return transport::cartan_schouten_transport<G>(0.5, groups::Side::Left, u, s, t, k, m); },
                                    reference, n));
    }
  }
}

// The generic ordered exponential for an n x n (here dynamic 5 x 5) generator
// A(t) = A0 + sin(3t) A1 + t^2 A2 has the same orders (reference: Magnus4, 4096 steps).
TEST(TransportConvergence, OrdersForADynamicMatrixGenerator) {
  std::mt19937 rng(kSeed + 7);
  using Mat = Eigen::MatrixXd;
  const Mat a0 = random_vector<Eigen::Matrix<double, 25, 1>>(rng, 0.6).reshaped(5, 5);
  const Mat a1 = random_vector<Eigen::Matrix<double, 25, 1>>(rng, 0.6).reshaped(5, 5);
  const Mat a2 = random_vector<Eigen::Matrix<double, 25, 1>>(rng, 0.6).reshaped(5, 5);
  std::function<Mat(double)> a = [&](double t) -> Mat { return a0 + std::sin(3 * t) * a1 + t * t * a2; };
  const double s = 0.5, t = 1.5;
  const Mat reference = transport::ordered_exp(a, s, t, 4096, transport::TransportMethod::Magnus4);
  for (transport::TransportMethod m : kMethods) {
    const int n = coarse_steps(m);
    expect_orders("5x5 function", m, observed_orders([&](int k) { return transport::ordered_exp(a, s, t, k, m); }, reference, n));
    expect_orders(
        "5x5 samples", m,
        observed_orders(
            [&](int k) { return transport::ordered_exp(transport::Samples{sample(a, s, t, k, false), sample(a, s, t, k, true), s, t}, m); },
            reference, n));
  }
  // Without midpoints the sampled path offers LieEuler and Magnus2 with the same results.
  const auto nodes = sample(a, s, t, 16, false), mids = sample(a, s, t, 16, true);
  for (transport::TransportMethod m : {transport::TransportMethod::LieEuler, transport::TransportMethod::Magnus2}) {
    EXPECT_NEAR_MATRIX(transport::ordered_exp(transport::Samples{nodes, {}, s, t}, m), transport::ordered_exp(transport::Samples{nodes, mids, s, t}, m), 0.0);
  }
  // The node version ends at the final value and starts at I.
  const auto path = transport::ordered_exp_nodes(transport::Samples{nodes, mids, s, t}, transport::TransportMethod::Magnus4);
  ASSERT_EQ(path.size(), nodes.size());
  EXPECT_NEAR_MATRIX(path.front(), Mat::Identity(5, 5), 0.0);
  EXPECT_NEAR_MATRIX(path.back(), transport::ordered_exp(transport::Samples{nodes, mids, s, t}, transport::TransportMethod::Magnus4), 0.0);
  const auto fpath = transport::ordered_exp_nodes(a, s, t, 16, transport::TransportMethod::Magnus4);
  ASSERT_EQ(fpath.size(), 17u);
  EXPECT_NEAR_MATRIX(fpath.back(), transport::ordered_exp(a, s, t, 16, transport::TransportMethod::Magnus4), 0.0);
  // The path's k-th value is the ordered exponential over [s, t_k] with k steps (same grid).
  EXPECT_NEAR_MATRIX(fpath[8], transport::ordered_exp(a, s, s + 0.5 * (t - s), 8, transport::TransportMethod::Magnus4), 1e-14);
}

// Every method is exact for a constant generator: exp((t - s) A), whatever the step count.
// Tolerance: products of 7 matrix exponentials of norm ~1: 1e-13.
TEST(OrderedExp, ConstantGeneratorIsTheMatrixExponential) {
  std::mt19937 rng(kSeed + 8);
  const Eigen::Matrix4d a = random_vector<Eigen::Matrix<double, 16, 1>>(rng, 1.0).reshaped(4, 4);
  const Eigen::Matrix4d expected = (1.5 * a).exp();
  for (transport::TransportMethod m : kMethods) {
    EXPECT_NEAR_MATRIX(transport::ordered_exp([&](double) { return a; }, 0.25, 1.75, 7, m), expected, 1e-13);
    EXPECT_EQ(order(m), m == transport::TransportMethod::LieEuler ? 1 : m == transport::TransportMethod::Magnus2 ? 2 : 4);
  }
}

// ------------------------------------------------------------------------------------------
// Bad input: std::invalid_argument whose message names the value.

TEST(TransportValidation, RejectsBadInput) {
  const auto conn = connections::cartan_schouten<groups::SO3>(0.5);
  auto u = [](double t) { return V3(t, 1, 0); };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto a = [](double t) { return Eigen::Matrix3d(t * Eigen::Matrix3d::Identity()); };

  expect_invalid([&] { transport::ordered_exp(a, 0, 1, 0, transport::TransportMethod::Magnus2); }, "steps = 0 must be at least 1");
  expect_invalid([&] { transport::ordered_exp_nodes(a, 0, 1, -3, transport::TransportMethod::Magnus2); }, "steps = -3");
  expect_invalid([&] { transport::transport_operator(conn, u, 0, 1, 0, transport::TransportMethod::LieEuler); },
                 "transport_operator: steps = 0");
  expect_invalid([&] { transport::cartan_schouten_transport<groups::SO3>(0.5, groups::Side::Left, u, 0, 1, 0, transport::TransportMethod::Magnus4); },
                 "cartan_schouten_transport: steps = 0");
  expect_invalid([&] { transport::ordered_exp(a, nan, 1, 4, transport::TransportMethod::Magnus2); }, "t0 = nan");
  expect_invalid([&] { transport::transport_operator(conn, u, 0, inf, 4, transport::TransportMethod::Magnus2); }, "t1 = inf");
  expect_invalid([&] { transport::cartan_schouten_transport<groups::SO3>(nan, groups::Side::Left, u, 0, 1, 4, transport::TransportMethod::Magnus2); },
                 "lambda = nan");
  // A generator or velocity that becomes non-finite: the message names the time.
  auto blows_up = [](double t) { return V3(1 / (t - 0.5), 0, 0); };
  expect_invalid([&] { transport::transport_operator(conn, blows_up, 0, 1, 2, transport::TransportMethod::LieEuler); },
                 "transport_operator: u(0.5) = [inf; 0; 0] contains a non-finite number");
  expect_invalid([&] { transport::cartan_schouten_transport<groups::SO3>(0.5, groups::Side::Left, blows_up, 0, 1, 2, transport::TransportMethod::LieEuler); },
                 "cartan_schouten_transport: u(0.5) = [inf; 0; 0] contains a non-finite number");
  expect_invalid(
      [&] {
        transport::ordered_exp([](double t) { return Eigen::Matrix2d(Eigen::Matrix2d::Constant(std::log(t))); }, 0, 0.5, 2,
                    transport::TransportMethod::LieEuler);
      },
      "ordered_exp: A(0) = [-inf, -inf; -inf, -inf] contains a non-finite number");
  expect_invalid(
      [&] {
        transport::ordered_exp([](double) { return Eigen::MatrixXd(Eigen::MatrixXd::Zero(2, 3)); }, 0, 1, 2,
                    transport::TransportMethod::LieEuler);
      },
      "is not square (2x3)");
  expect_invalid(
      [&] {
        transport::ordered_exp([](double t) { return Eigen::MatrixXd(Eigen::MatrixXd::Zero(t > 0.3 ? 3 : 2, t > 0.3 ? 3 : 2)); },
                    0, 1, 2, transport::TransportMethod::LieEuler);
      },
      "has shape 3x3, expected 2x2");

  // Samples: counts, missing midpoints, non-finite entries, shapes.
  const std::vector<V3> u_nodes = {V3(0, 1, 0), V3(1, 1, 0), V3(2, 1, 0)};
  const std::vector<V3> u_mids = {V3(0.5, 1, 0), V3(1.5, 1, 0)};
  expect_invalid([&] { transport::transport_operator(conn, transport::Samples{std::vector<V3>{V3::Zero()}, {}, 0, 1}, transport::TransportMethod::Magnus2); },
                 "u_nodes.size() = 1 must be at least 2");
  expect_invalid([&] { transport::transport_operator(conn, transport::Samples{u_nodes, {}, 0, 1}, transport::TransportMethod::Magnus4); },
                 "method = Magnus4 needs midpoint samples");
  expect_invalid(
      [&] {
        transport::ordered_exp(transport::Samples{std::vector<Eigen::Matrix3d>(3, Eigen::Matrix3d::Zero()), {}, 0, 1}, transport::TransportMethod::Magnus4);
      },
      "method = Magnus4 needs midpoint samples");
  expect_invalid(
      [&] { transport::cartan_schouten_transport<groups::SO3>(0.5, groups::Side::Left, transport::Samples{u_nodes, {}, 0, 1}, transport::TransportMethod::Magnus4); },
      "method = Magnus4");
  expect_invalid(
      [&] { transport::transport_operator(conn, transport::Samples{u_nodes, std::vector<V3>{V3::Zero()}, 0, 1}, transport::TransportMethod::Magnus4); },
      "u_midpoints.size() = 1 must be u_nodes.size() - 1 = 2");
  std::vector<V3> bad_nodes = u_nodes;
  bad_nodes[2][1] = nan;
  expect_invalid([&] { transport::transport_operator(conn, transport::Samples{bad_nodes, {}, 0, 1}, transport::TransportMethod::Magnus2); },
                 "u_nodes[2] = [");
  expect_invalid(
      [&] { transport::cartan_schouten_transport<groups::SO3>(0.5, groups::Side::Right, transport::Samples{bad_nodes, {}, 0, 1}, transport::TransportMethod::LieEuler); },
      "u_nodes[2]");
  std::vector<V3> bad_mids = u_mids;
  bad_mids[0][0] = inf;
  expect_invalid([&] { transport::transport_operator(conn, transport::Samples{u_nodes, bad_mids, 0, 1}, transport::TransportMethod::Magnus4); },
                 "u_midpoints[0] = [inf");
  expect_invalid([&] { transport::transport_operator(conn, transport::Samples{u_nodes, u_mids, 0, nan}, transport::TransportMethod::Magnus4); },
                 "t1 = nan");
  std::vector<Eigen::MatrixXd> ragged = {Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(3, 3)};
  expect_invalid([&] { transport::ordered_exp(transport::Samples{ragged, {}, 0, 1}, transport::TransportMethod::LieEuler); },
                 "nodes[1] = [0, 0, 0; 0, 0, 0; 0, 0, 0] has shape 3x3, expected 2x2");
  expect_invalid(
      [&] {
        transport::ordered_exp(transport::Samples{std::vector<Eigen::MatrixXd>(2, Eigen::MatrixXd::Zero(2, 3)), {}, 0, 1}, transport::TransportMethod::LieEuler);
      },
      "nodes[0] = [0, 0, 0; 0, 0, 0] is not square (2x3)");
  // Ambient helpers validate the points.
  Eigen::Matrix3d not_rotation = 2 * Eigen::Matrix3d::Identity();
  expect_invalid(
      [&] {
        transport::transport_tangent<groups::SO3>(groups::Side::Left, Eigen::Matrix3d::Identity(), not_rotation, Eigen::Matrix3d::Identity(),
                               Eigen::Matrix3d::Zero());
      },
      "g_s = [2, 0, 0");
}

}  // namespace
}  // namespace cartan::testing
