// The geometry of Cartan–Schouten connections that the paper states (§3, §5), each checked
// against something other than the formulas cartan evaluates:
//   * nabla T = nabla R = 0: parallel transport along random curves maps T and R to themselves;
//   * geodesics are translates of one-parameter subgroups (Cartan connections), and the geodesics
//     of a Levi-Civita connection are the Euler–Arnold motions;
//   * lambda = 1/2 is the Levi-Civita connection of the bi-invariant metric on SO(3);
//   * holonomy around closed loops: the identity for lambda = 0, 1, and -area R(a, b) for small
//     loops at lambda = 1/2;
//   * the exchange of derivatives (eq:exchange-der-left-conn, eq:exchange-der-right-conn) and the
//     variation of the transported velocity (eq:delta-v-lie-lambda), by finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <type_traits>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/mechanics/euler_poincare.hpp"
#include "cartan/mechanics/geodesic.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/transport/parallel_transport.hpp"
#include "cartan/testing/connection_identities.hpp"
#include "test_support.hpp"
#include "mechanics/mechanics_support.hpp"

namespace cartan::testing {
namespace {

using groups::SO3;
using transport::TransportMethod;

/// A smooth curve exp(x(t)) with x(t) = t a + t^2 b + sin(t) c, and its velocity trivialised on
/// `side` by differences of the curve (fourth order, step 1e-4: error ~1e-13).
template <groups::LieGroup G>
struct TestCurve {
  groups::TangentOf<G> a, b, c;
  groups::ElementOf<G> operator()(double t) const {
    return G::exp(groups::TangentOf<G>(t * a + t * t * b + std::sin(t) * c));
  }
  groups::TangentOf<G> velocity(groups::Side side, double t) const {
    return trivialised_derivative<G>(side, [&](double e) { return (*this)(t + e); }, 1e-4);
  }
};

template <groups::LieGroup G>
TestCurve<G> random_curve(std::mt19937& rng) {
  return {random_tangent<G>(rng), random_tangent<G>(rng, 0.5), random_tangent<G>(rng, 0.5)};
}

/// The trivialised transport operator P(0 -> t) along the curve (Magnus4, 200 steps: the
/// error of a smooth O(1) generator is ~1e-11).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> transport_along(const connections::InvariantConnection<G>& connection, const TestCurve<G>& curve,
                                           double t) {
  return transport::transport_operator<G>(connection, [&](double r) { return curve.velocity(connection.side(), r); }, 0.0,
                                          t, 200, TransportMethod::Magnus4);
}

// nabla T = 0 and nabla R = 0 (paper §5, after tor-cur-lie-alg) mean that parallel transport
// preserves the tensors: P T(v, w) = T(P v, P w) and P R(a, b) c = R(P a, P b) P c along any
// curve. Checked along random curves on SO(3) and SE(3), both descriptions, for several lambda;
// a generic connection violates it by O(0.1-1) (negative control). Tolerance: the transport's
// error ~1e-11 times O(1) tensors.
template <groups::LieGroup G>
void expect_parallel_tensors(std::mt19937& rng) {
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    for (double lambda : {0.0, 0.3, 0.5, 1.0, 1.4}) {
      const auto connection = connections::cartan_schouten<G>(lambda, side);
      const TestCurve<G> curve = random_curve<G>(rng);
      const auto p = transport_along(connection, curve, 1.3);
      const auto a = random_tangent<G>(rng), b = random_tangent<G>(rng), c = random_tangent<G>(rng);
      const groups::TangentOf<G> pa = p * a, pb = p * b, pc = p * c;
      EXPECT_LE(max_abs_diff(p * connection.torsion(a, b), connection.torsion(pa, pb)), 1e-9) << lambda;
      EXPECT_LE(max_abs_diff(p * connection.curvature(a, b, c), connection.curvature(pa, pb, pc)), 1e-9) << lambda;
    }
    const auto generic = random_connection<G>(side, rng);
    const TestCurve<G> curve = random_curve<G>(rng);
    const auto p = transport_along(generic, curve, 1.3);
    const auto a = random_tangent<G>(rng), b = random_tangent<G>(rng);
    EXPECT_GT(max_abs_diff(p * generic.torsion(a, b), generic.torsion(groups::TangentOf<G>(p * a), groups::TangentOf<G>(p * b))),
              1e-2);
  }
}

TEST(CartanSchoutenGeometry, TorsionAndCurvatureAreParallel) {
  std::mt19937 rng(kSeed + 70);
  expect_parallel_tensors<SO3>(rng);
  expect_parallel_tensors<groups::SE3>(rng);
  expect_parallel_tensors<groups::Heisenberg>(rng);
}

// Geodesics of a Cartan connection are g0 exp(t v0) (paper §5, "Cartan connections"): with
// nabla_v v = 0 the RKMK4 steps reproduce the subgroup to rounding (20 steps of O(1) products:
// 1e-13). A connection with a symmetric part bends them (negative control).
template <groups::LieGroup G>
void expect_subgroup_geodesics(std::mt19937& rng) {
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    const groups::ElementOf<G> g0 = random_element<G>(rng);
    const groups::TangentOf<G> v0 = random_tangent<G>(rng);
    for (double lambda : {0.0, 0.5, 1.0, 1.7}) {
      const auto path = mechanics::geodesic<G>(connections::cartan_schouten<G>(lambda, side), g0, v0, 2.0, 20);
      for (std::size_t k = 0; k < path.t.size(); ++k) {
        const groups::TangentOf<G> tv = path.t[k] * v0;
        const groups::ElementOf<G> expected = side == groups::Side::Left ? G::compose(g0, G::exp(tv)) : G::compose(G::exp(tv), g0);
        EXPECT_LE(max_abs_diff(path.g[k], expected), 1e-12) << lambda << ' ' << to_string(side);
      }
    }
    // A quarter of the speed keeps the quadratic rate -nabla_v v of a random map from blowing up.
    const auto bent = mechanics::geodesic<G>(random_connection<G>(side, rng), g0, groups::TangentOf<G>(v0 / 4), 2.0, 20);
    const groups::TangentOf<G> tv = 0.5 * v0;
    const groups::ElementOf<G> subgroup = side == groups::Side::Left ? G::compose(g0, G::exp(tv)) : G::compose(G::exp(tv), g0);
    EXPECT_GT(max_abs_diff(bent.g.back(), subgroup), 1e-2);
  }
}

TEST(CartanSchoutenGeometry, GeodesicsAreOneParameterSubgroups) {
  std::mt19937 rng(kSeed + 71);
  expect_subgroup_geodesics<SO3>(rng);
  expect_subgroup_geodesics<groups::SE3>(rng);
  expect_subgroup_geodesics<groups::Heisenberg>(rng);
}

/// The Levi-Civita connection of the left-invariant metric <u, w> = u . I w (Koszul formula):
/// nabla_u w = 1/2 ([u, w] - I^{-1} (ad_u^T I w + ad_w^T I u)).
connections::InvariantConnection<SO3> levi_civita(const Eigen::Matrix3d& inertia) {
  const Eigen::Matrix3d inverse = inertia.inverse();
  return connections::InvariantConnection<SO3>::from_bilinear(groups::Side::Left, [&](const SO3::Tangent& u, const SO3::Tangent& w) {
    return SO3::Tangent(0.5 * (groups::bracket<SO3>(u, w) -
                               inverse * (SO3::ad(u).transpose() * inertia * w + SO3::ad(w).transpose() * inertia * u)));
  });
}

// The geodesics of the Levi-Civita connection of I are the free rigid body's motions
// (Euler–Arnold): v' = -nabla_v v = I^{-1} ad_v^T I v is eq:EP-left for l = 1/2 v . I v. Both
// integrators are RKMK4 with the same steps on mathematically equal rates: agreement to 1e-12.
TEST(CartanSchoutenGeometry, LeviCivitaGeodesicsAreEulerArnoldMotions) {
  const Eigen::Matrix3d inertia = Eigen::Vector3d(2.0, 3.0, 4.0).asDiagonal();
  const SO3::Element g0 = SO3::exp(SO3::Tangent(0.2, -0.4, 0.3));
  const SO3::Tangent v0(0.8, -0.5, 0.6);
  const auto path = mechanics::geodesic<SO3>(levi_civita(inertia), g0, v0, 10.0, 400);
  const auto body = mechanics::euler_poincare<SO3>(groups::Side::Left, mechanics::RigidBody(inertia), g0, v0, 10.0, 400);
  for (std::size_t k = 0; k < path.t.size(); ++k) {
    EXPECT_LE(max_abs_diff(path.g[k], body.g[k]), 1e-12);
    EXPECT_LE(max_abs_diff(path.mu[k], body.v[k]), 1e-12);
  }
}

// lambda = 1/2 on SO(3) is the Levi-Civita connection of the bi-invariant metric u . w (paper §5,
// remark (ii)): the Koszul formula with I = identity gives 1/2 [u, w] coefficient by coefficient,
// and, as a property of the transport, P is orthogonal along any curve (metric) while T = 0.
// With I = diag(2, 3, 4) (left- but not bi-invariant) it is another connection.
TEST(CartanSchoutenGeometry, HalfIsTheLeviCivitaConnectionOfTheBiInvariantMetric) {
  const auto half = connections::cartan_schouten<SO3>(0.5);
  const auto lc = levi_civita(Eigen::Matrix3d::Identity());
  for (int i = 0; i < 3; ++i) EXPECT_LE(max_abs_diff(half.coefficients()[i], lc.coefficients()[i]), 1e-15);
  const auto other = levi_civita(Eigen::Vector3d(2.0, 3.0, 4.0).asDiagonal());
  double difference = 0;
  for (int i = 0; i < 3; ++i) difference = std::max(difference, max_abs_diff(half.coefficients()[i], other.coefficients()[i]));
  EXPECT_GT(difference, 0.1);
  std::mt19937 rng(kSeed + 72);
  const auto p = transport_along(half, random_curve<SO3>(rng), 1.5);
  EXPECT_LE(max_abs_diff(p.transpose() * p, Eigen::Matrix3d::Identity()), 1e-10);
}

// Holonomy around the closed loop x(t) = eps (cos t a + sin t b), g = exp(x), t in [0, 2 pi]: the
// transport of the flat connections lambda = 0 (left translation) and 1 (right translation) is
// the identity (to the transport's 1e-11), and lambda = 1/2 has holonomy I - A R(a, b) + O(eps^3)
// with the enclosed area A = pi eps^2: the relative deviation is O(eps), measured at two eps.
TEST(CartanSchoutenGeometry, HolonomyAroundLoops) {
  const SO3::Tangent a(1.0, 0.2, -0.3), b(-0.1, 0.8, 0.5);
  const auto holonomy = [&](double lambda, double eps) {
    const auto loop_velocity = [&, eps](double t) {
      const auto point = [&](double s) { return SO3::exp(SO3::Tangent(eps * (std::cos(s) * a + std::sin(s) * b))); };
      return trivialised_derivative<SO3>(groups::Side::Left, [&](double e) { return point(t + e); }, 1e-4);
    };
    return transport::transport_operator<SO3>(connections::cartan_schouten<SO3>(lambda), loop_velocity, 0.0,
                                              2 * std::numbers::pi, 400, TransportMethod::Magnus4);
  };
  for (double lambda : {0.0, 1.0}) {
    EXPECT_LE(max_abs_diff(holonomy(lambda, 0.5), Eigen::Matrix3d::Identity()), 1e-10) << lambda;
  }
  const auto half = connections::cartan_schouten<SO3>(0.5);
  Eigen::Matrix3d r_ab;
  for (int i = 0; i < 3; ++i) r_ab.col(i) = half.curvature(a, b, SO3::Tangent::Unit(i));
  std::vector<double> deviations;
  for (double eps : {0.1, 0.05}) {
    const double area = std::numbers::pi * eps * eps;
    const Eigen::Matrix3d expected = Eigen::Matrix3d::Identity() - area * r_ab;
    const double deviation = (holonomy(0.5, eps) - expected).norm() / (area * r_ab.norm());
    std::cout << "[ measured ] holonomy at lambda = 1/2, eps = " << eps << ": |P - (I - A R)| / |A R| = " << deviation << '\n';
    deviations.push_back(deviation);
  }
  EXPECT_LE(deviations[0], 0.2);
  EXPECT_LT(deviations[1], 0.6 * deviations[0]);  // O(eps): halves with eps
  EXPECT_GT((holonomy(0.5, 0.1) - Eigen::Matrix3d::Identity()).norm(), 1e-3);
}

// eq:exchange-der-left-conn and eq:exchange-der-right-conn on the two-parameter map
// g_s(t) = exp(x(s, t)), by nested fourth-order differences (steps 1e-3: error ~1e-9); the
// bracket is 0.02-1 here. A sign error would fail by twice that.
template <groups::LieGroup G>
void expect_exchange_of_derivatives(std::mt19937& rng) {
  using Tangent = groups::TangentOf<G>;
  const Tangent a = random_tangent<G>(rng), b = random_tangent<G>(rng), c = random_tangent<G>(rng, 0.5);
  const auto map = [&](double s, double t) { return G::exp(Tangent(s * a + t * b + s * t * c + std::sin(s + 2 * t) * a)); };
  constexpr double kStep = 1e-3;
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    // Trivialised partial derivatives: left g^{-1} dg, right dg g^{-1}.
    const auto trivialised = [&](double s, double t, bool along_t) {
      return trivialised_derivative<G>(side, [&](double e) { return along_t ? map(s, t + e) : map(s + e, t); }, kStep);
    };
    const double s = 0.3, t = -0.4;
    const Tangent dt_along_s = derivative([&](double e) { return trivialised(s + e, t, true); }, kStep);
    const Tangent ds_along_t = derivative([&](double e) { return trivialised(s, t + e, false); }, kStep);
    const Tangent v_t = trivialised(s, t, true), v_s = trivialised(s, t, false);
    const Tangent expected = side == groups::Side::Left ? groups::bracket<G>(v_t, v_s) : groups::bracket<G>(v_s, v_t);
    EXPECT_LE(max_abs_diff(dt_along_s - ds_along_t, expected), 1e-7) << to_string(side);
    EXPECT_GT(expected.norm(), 1e-2);  // the bracket is not negligible against the tolerance
  }
}

TEST(CartanSchoutenGeometry, ExchangeOfDerivatives) {
  std::mt19937 rng(kSeed + 73);
  expect_exchange_of_derivatives<SO3>(rng);
  expect_exchange_of_derivatives<groups::SE3>(rng);
  expect_exchange_of_derivatives<groups::Heisenberg>(rng);
}

// (eq:variation-der): along a two-parameter family g_e(t), the covariant derivative in e of the
// velocity is D/dt dg - T(g', dg). Trivialised (eq:cov-curve-left): d_e u + nabla_w u =
// d_t w + nabla_u w - T(u, w) with u = g^{-1} d_t g, w = g^{-1} d_e g (left; right: dg g^{-1}).
// By nested differences on SO(3) and SE(3) with random (non-Cartan) connections; each side O(1).
template <groups::LieGroup G>
void expect_variation_of_the_velocity(std::mt19937& rng) {
  using Tangent = groups::TangentOf<G>;
  const Tangent a = random_tangent<G>(rng), b = random_tangent<G>(rng), c = random_tangent<G>(rng, 0.5);
  const auto map = [&](double e, double t) { return G::exp(Tangent(t * a + e * std::sin(t) * b + e * t * t * c)); };
  constexpr double kStep = 1e-3;
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    const auto connection = random_connection<G>(side, rng);
    const auto trivialised = [&](double e, double t, bool along_t) {
      return trivialised_derivative<G>(side, [&](double d) { return along_t ? map(e, t + d) : map(e + d, t); }, kStep);
    };
    const double t = 0.7;
    const Tangent u = trivialised(0, t, true), w = trivialised(0, t, false);
    const Tangent de_u = derivative([&](double e) { return trivialised(e, t, true); }, kStep);
    const Tangent dt_w = derivative([&](double d) { return trivialised(0, t + d, false); }, kStep);
    const Tangent lhs = connection.covariant_derivative(w, u, de_u);
    const Tangent rhs = Tangent(connection.covariant_derivative(u, w, dt_w) - connection.torsion(u, w));
    EXPECT_LE(max_abs_diff(lhs, rhs), 1e-7) << to_string(side);
    EXPECT_GT(connection.torsion(u, w).norm(), 0.1);
  }
}

TEST(CartanSchoutenGeometry, VariationOfTheVelocity) {
  std::mt19937 rng(kSeed + 74);
  expect_variation_of_the_velocity<SO3>(rng);
  expect_variation_of_the_velocity<groups::SE3>(rng);
}

// (bracket-basis): [V, W]_g = g (V(g^{-1} W) - W(g^{-1} V) + [g^{-1} V, g^{-1} W]) for non-invariant
// fields V = g f(g), W = g k(g), against the bracket of vector fields in the ambient coordinates of
// the group's elements (3 x 3 matrices for SO(3), (a, b, c) for H3): [V, W] = DW.V - DV.W, each a
// derivative along a curve through g with that velocity. Nested differences: 1e-7.
template <groups::LieGroup G>
void expect_bracket_of_fields(std::mt19937& rng) {
  using Tangent = groups::TangentOf<G>;
  const SmoothField<G> f_field(rng), k_field(rng);
  const groups::ElementOf<G> g = random_element<G>(rng);
  const auto trivial = [](const SmoothField<G>& field, const groups::ElementOf<G>& x) { return G::left_trivialise(x, field(x)); };
  const Tangent f = trivial(f_field, g), k = trivial(k_field, g);
  const auto along = [&](const Tangent& direction, double e) { return G::compose(g, G::exp(Tangent(e * direction))); };
  const auto ambient_derivative = [&](const SmoothField<G>& field, const Tangent& direction) {
    return derivative([&](double e) { return groups::ElementOf<G>(field(along(direction, e))); }, 1e-3);
  };
  const groups::ElementOf<G> ambient = ambient_derivative(k_field, f) - ambient_derivative(f_field, k);
  const Tangent v_k = derivative([&](double e) { return trivial(k_field, along(f, e)); }, 1e-3);
  const Tangent w_f = derivative([&](double e) { return trivial(f_field, along(k, e)); }, 1e-3);
  const groups::ElementOf<G> formula = G::left_translate(g, Tangent(v_k - w_f + groups::bracket<G>(f, k)));
  EXPECT_LE(max_abs_diff(ambient, formula), 1e-7);
  EXPECT_GT(max_abs_diff(ambient, G::left_translate(g, Tangent(v_k - w_f))), 0.05);  // the bracket term matters
}

TEST(CartanSchoutenGeometry, BracketOfVectorFields) {
  std::mt19937 rng(kSeed + 75);
  expect_bracket_of_fields<SO3>(rng);
  expect_bracket_of_fields<groups::Heisenberg>(rng);
}

// eq:delta-v-lie-lambda: for the variation g_e(t) = g(t) exp(e w_-(t)) with w_-(0) = w_-(T) = 0,
// the transported velocity v_e(t) = P_e(0 -> t)^{-1} g_e^{-1} g_e' (left-trivialised at g(0))
// varies by
//   dv = w' - (2 lambda - 1) ad_v w - lambda (1 - lambda) ad_v int_0^t ad_v(r) w(r) dr,
// with w(t) = P(0 -> t)^{-1} w_-(t) the transported variation. Both sides by differences and
// quadrature: dv by a fourth-order difference in e (step 1e-3) of transports computed with
// Magnus4 (error ~1e-10), w' likewise in t, the integral by Simpson's rule on 200 intervals
// (error ~1e-9): tolerance 1e-6 on O(1) values.
TEST(CartanSchoutenGeometry, VariationOfTheTransportedVelocity) {
  const SO3::Tangent a(0.7, -0.4, 0.5), b(0.2, 0.3, -0.6), c1(0.5, 0.9, -0.3), c2(-0.6, 0.2, 0.8);
  const double T = 1.2;
  const auto curve = [&](double t) { return SO3::exp(SO3::Tangent(t * a + t * t * b)); };
  const auto w_minus = [&](double t) { return SO3::Tangent(std::sin(std::numbers::pi * t / T) * c1 + t * (T - t) * c2); };
  const auto varied = [&](double e) {
    return [&, e](double t) { return SO3::compose(curve(t), SO3::exp(SO3::Tangent(e * w_minus(t)))); };
  };
  const auto body_velocity = [](const auto& g, double t) {
    return trivialised_derivative<SO3>(groups::Side::Left, [&](double e) { return g(t + e); }, 1e-4);
  };
  for (double lambda : {0.0, 0.5, 0.8, 1.0}) {
    const auto connection = connections::cartan_schouten<SO3>(lambda);
    const auto transport = [&](const auto& g, double t) -> Eigen::Matrix3d {
      if (t == 0) return Eigen::Matrix3d::Identity();
      return transport::transport_operator<SO3>(connection, [&](double r) { return body_velocity(g, r); }, 0.0, t, 200,
                                                TransportMethod::Magnus4);
    };
    const auto transported_velocity = [&](const auto& g, double t) -> SO3::Tangent {
      return transport(g, t).lu().solve(body_velocity(g, t));
    };
    const auto w = [&](double t) -> SO3::Tangent { return transport(curve, t).lu().solve(w_minus(t)); };
    for (double t : {0.35, 0.8}) {
      const SO3::Tangent dv = derivative([&](double e) { return transported_velocity(varied(e), t); }, 1e-3);
      const SO3::Tangent v = transported_velocity(curve, t);
      const SO3::Tangent w_dot = derivative([&](double e) { return w(t + e); }, 1e-3);
      // Simpson's rule on the nodes r_k = k t / 200, with P(0 -> r_k) from one transport.
      constexpr int kIntervals = 200;
      const auto p = transport::transport_operator_nodes<SO3>(
          connection, [&](double r) { return body_velocity(curve, r); }, 0.0, t, kIntervals, TransportMethod::Magnus4);
      SO3::Tangent integral = SO3::Tangent::Zero();
      for (int k = 0; k <= kIntervals; ++k) {
        const double r = t * k / kIntervals, weight = (k == 0 || k == kIntervals) ? 1 : (k % 2 ? 4 : 2);
        const Eigen::PartialPivLU<Eigen::Matrix3d> lu(p[static_cast<std::size_t>(k)]);
        integral += weight * groups::bracket<SO3>(SO3::Tangent(lu.solve(body_velocity(curve, r))),
                                                  SO3::Tangent(lu.solve(w_minus(r))));
      }
      integral *= t / (3 * kIntervals);
      const SO3::Tangent formula = w_dot - (2 * lambda - 1) * groups::bracket<SO3>(v, w(t)) -
                                   lambda * (1 - lambda) * groups::bracket<SO3>(v, integral);
      EXPECT_LE(max_abs_diff(dv, formula), 1e-6) << "lambda " << lambda << ", t " << t;
      if (lambda == 0.5) {
        EXPECT_GT((lambda * (1 - lambda) * groups::bracket<SO3>(v, integral)).norm(), 1e-2);  // the curvature term matters
      }
    }
  }
}

}  // namespace
}  // namespace cartan::testing
