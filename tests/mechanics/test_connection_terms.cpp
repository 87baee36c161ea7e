// Each connection term of the global Euler–Lagrange equation (EL-Lie, eq:EL-1) and of the global
// Hamilton equations (Hamilton-Lie, eq:HE-1), as cartan evaluates them in trivialised form
// (euler_lagrange_terms, hamilton_terms), against its coordinate definition in the chart
// x -> g exp(x) (left connections) or x -> exp(x) g (right connections):
//   Christoffel symbols   nabla_{d_i} d_j = Gamma^k_ij d_k from (eq:left-conn) applied to the
//                         coordinate fields, whose trivialisations F_j(x) are differences of exp;
//   vertical/horizontal   d_x' F = dF/dx'^k dx^k (eq:vert-diff), d^nabla_x F = (dF/dx^i -
//                         Gamma^k_ij x'^j dF/dx'^k) dx^i (eq:hor-diff-1) and, on T*G,
//                         (dF/dx^i + Gamma^k_ij p_k dF/dp_j) dx^i (eq:hor-diff-2);
//   torsion               T(d_j, d_i) = (Gamma^k_ji - Gamma^k_ij) d_k (coordinate fields commute);
//   covariant derivative  (D/dt p)_i = p_i' - Gamma^k_ji x'^j p_k along a curve.
// Nothing here uses the trivialised formulas: only exp, log, the connection's bilinear map and the
// models' values. Then the Hamilton integrator: eq:LP-left/right for every connection, and the
// Legendre transform of the Euler–Lagrange trajectory.
#include <gtest/gtest.h>

#include <array>
#include <type_traits>

#include "cartan/mechanics/euler_lagrange.hpp"
#include "cartan/mechanics/euler_poincare.hpp"
#include "cartan/mechanics/hamilton.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/lie_poisson.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/transport/parallel_transport.hpp"
#include "mechanics/mechanics_support.hpp"

namespace cartan::testing {
namespace {

/// The exponential chart at g on the connection's side, its coordinate fields and Christoffel
/// symbols, all by differences (steps 1e-3: fourth-order differences with errors ~1e-12 for the
/// frame and ~1e-9 for its derivative, nested).
template <groups::LieGroup G>
struct ExpChart {
  using Tangent = groups::TangentOf<G>;
  using Matrix = groups::AlgebraMatrixOf<G>;
  static constexpr int n = G::kDim;
  static constexpr double kStep = 1e-3;
  groups::Side side;
  groups::ElementOf<G> g;

  groups::ElementOf<G> point(const Tangent& x) const {
    return side == groups::Side::Left ? G::compose(g, G::exp(x)) : G::compose(G::exp(x), g);
  }
  /// Column j: the trivialised coordinate field F_j(x) = g(x)^{-1} d_j g(x) (left) or
  /// d_j g(x) g(x)^{-1} (right).
  Matrix frame(const Tangent& x) const {
    Matrix f;
    for (int j = 0; j < n; ++j) {
      f.col(j) = trivialised_derivative<G>(side, [&](double e) { return point(Tangent(x + e * Tangent::Unit(j))); }, kStep);
    }
    return f;
  }
  /// Gamma[i].col(j) = the components of nabla_{d_i} d_j at x = 0: (eq:left-conn) with
  /// V = d_i, W = d_j: d_i F_j + nabla_{F_i} F_j, where F(0) = I.
  std::array<Matrix, n> christoffel(const connections::InvariantConnection<G>& connection) const {
    std::array<Matrix, n> gamma;
    for (int i = 0; i < n; ++i) {
      const Matrix d_frame = derivative([&](double e) -> Matrix { return frame(Tangent(e * Tangent::Unit(i))); }, kStep);
      for (int j = 0; j < n; ++j) gamma[i].col(j) = d_frame.col(j) + connection.nabla(Tangent::Unit(i), Tangent::Unit(j));
    }
    return gamma;
  }
};

/// Coordinate forms at x = 0 (header comment): torsion_i = p_k T^k(x', d_i), the Christoffel part
/// of the covariant derivative of p along the curve, -Gamma^k_ji x'^j p_k (the trivialised term
/// `covariant` also holds the frame's derivative, so it is checked along a curve below), and that
/// of the horizontal differential, Gamma^k_ij x'^j p_k (to be subtracted on TG, added on T*G).
template <groups::LieGroup G>
struct CoordinateTerms {
  groups::CovectorOf<G> torsion, covariant, christoffel_part;
};

template <groups::LieGroup G>
CoordinateTerms<G> coordinate_terms(const std::array<groups::AlgebraMatrixOf<G>, G::kDim>& gamma,
                                    const groups::TangentOf<G>& xdot, const groups::CovectorOf<G>& p) {
  CoordinateTerms<G> out;
  for (int i = 0; i < G::kDim; ++i) {
    groups::TangentOf<G> gamma_ji_xdot = groups::TangentOf<G>::Zero(), gamma_ij_xdot = groups::TangentOf<G>::Zero();
    for (int j = 0; j < G::kDim; ++j) {
      gamma_ji_xdot += xdot[j] * gamma[j].col(i);
      gamma_ij_xdot += xdot[j] * gamma[i].col(j);
    }
    out.torsion[i] = p.dot(gamma_ji_xdot - gamma_ij_xdot);
    out.covariant[i] = -p.dot(gamma_ji_xdot);
    out.christoffel_part[i] = p.dot(gamma_ij_xdot);
  }
  return out;
}

// Tolerances: the Christoffel symbols come from nested fourth-order differences of exp/log (step
// 1e-3: truncation ~1e-12, rounding 1e-16 / 1e-6 ~ 1e-10); the terms are O(1) sums of them, so
// 1e-7 is three orders above the error and still far below the O(0.1-1) size of each term
// (checked: a wrong sign or a missing Gamma fails by 1e-1).
constexpr double kTermTolerance = 1e-7;

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void expect_euler_lagrange_terms_match(const std::string& what, const connections::InvariantConnection<G>& connection,
                                       const L& lagrangian, std::mt19937& rng) {
  using Tangent = groups::TangentOf<G>;
  const ExpChart<G> chart{connection.side(), random_element<G>(rng, 0.8)};
  const auto gamma = chart.christoffel(connection);
  const Tangent v = random_tangent<G>(rng, 1.5);
  const groups::CovectorOf<G> mu = lagrangian.momentum(0.0, chart.g, v), zeta = lagrangian.group_gradient(0.0, chart.g, v);
  const auto terms = mechanics::euler_lagrange_terms<G>(connection, v, mu, zeta);
  // L in coordinates: F(x, x') = l(g(x), F(x) x'); at x = 0 the velocity is v and dF/dx' = mu.
  groups::CovectorOf<G> d_x;
  for (int i = 0; i < G::kDim; ++i) {
    d_x[i] = derivative(
        [&](double e) {
          const Tangent x = e * Tangent::Unit(i);
          return lagrangian.value(0.0, chart.point(x), Tangent(chart.frame(x) * v));
        },
        ExpChart<G>::kStep);
  }
  const CoordinateTerms<G> c = coordinate_terms<G>(gamma, v, mu);
  EXPECT_LE(max_abs_diff(terms.horizontal, d_x - c.christoffel_part), kTermTolerance) << what << " (eq:hor-diff-1)";
  EXPECT_LE(max_abs_diff(terms.torsion, c.torsion), kTermTolerance) << what << " (torsion)";
}

template <groups::LieGroup G, mechanics::ReducedHamiltonian<G> H>
void expect_hamilton_terms_match(const std::string& what, const connections::InvariantConnection<G>& connection,
                                 const H& hamiltonian, std::mt19937& rng) {
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;
  const ExpChart<G> chart{connection.side(), random_element<G>(rng, 0.8)};
  const auto gamma = chart.christoffel(connection);
  const Covector mu = random_tangent<G>(rng, 1.5);
  const Tangent v = hamiltonian.velocity(0.0, chart.g, mu);
  const auto terms = mechanics::hamilton_terms<G>(connection, v, mu, hamiltonian.group_gradient(0.0, chart.g, mu));
  // H in coordinates: F(x, p) = h(g(x), mu(x, p)), mu . F_j(x) = p_j; at x = 0, p = mu and dF/dp = v.
  Covector d_x;
  for (int i = 0; i < G::kDim; ++i) {
    d_x[i] = derivative(
        [&](double e) {
          const Tangent x = e * Tangent::Unit(i);
          return hamiltonian.value(0.0, chart.point(x), Covector(chart.frame(x).transpose().lu().solve(mu)));
        },
        ExpChart<G>::kStep);
  }
  const CoordinateTerms<G> c = coordinate_terms<G>(gamma, v, mu);
  EXPECT_LE(max_abs_diff(terms.horizontal, d_x + c.christoffel_part), kTermTolerance) << what << " (eq:hor-diff-2)";
  EXPECT_LE(max_abs_diff(terms.torsion, c.torsion), kTermTolerance) << what << " (torsion)";
}

/// The right-reduced form of a left-reduced Lagrangian or Hamiltonian (mechanics/right_reduced.hpp).
template <groups::LieGroup G, class Model>
auto right_reduced(const Model& model) {
  if constexpr (mechanics::ReducedLagrangian<Model, G>) {
    return mechanics::right_reduced_lagrangian<G>(model);
  } else {
    return mechanics::right_reduced_hamiltonian<G>(model);
  }
}

/// Runs check(what, connection, model) for the SO(3) and H3 oscillators (left-reduced for left
/// connections, right-reduced for right ones) under every connection of connections_on.
template <class Check>
void for_each_oscillator_and_connection(const auto& so3_model, const auto& h3_model, const Check& check) {
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    const bool left = side == groups::Side::Left;
    for (const auto& [name, connection] : connections_on<groups::SO3>(side)) {
      const std::string what = "SO(3) oscillator, " + std::string(to_string(side)) + ", " + name;
      if (left) {
        check(what, connection, so3_model);
      } else {
        check(what, connection, right_reduced<groups::SO3>(so3_model));
      }
    }
    for (const auto& [name, connection] : connections_on<groups::Heisenberg>(side)) {
      const std::string what = "H3 oscillator, " + std::string(to_string(side)) + ", " + name;
      if (left) {
        check(what, connection, h3_model);
      } else {
        check(what, connection, right_reduced<groups::Heisenberg>(h3_model));
      }
    }
  }
}

TEST(ConnectionTerms, EulerLagrangeTermsAreTheirCoordinateDefinitions) {
  std::mt19937 rng(kSeed + 60);
  for_each_oscillator_and_connection(mechanics::SO3Oscillator(kInertia), mechanics::h3_oscillator(),
                                     [&](const std::string& what, const auto& connection, const auto& model) {
                                       expect_euler_lagrange_terms_match(what, connection, model, rng);
                                     });
}

TEST(ConnectionTerms, HamiltonTermsAreTheirCoordinateDefinitions) {
  std::mt19937 rng(kSeed + 61);
  for_each_oscillator_and_connection(mechanics::SO3OscillatorHamiltonian(kInertia), mechanics::h3_oscillator_hamiltonian(),
                                     [&](const std::string& what, const auto& connection, const auto& model) {
                                       expect_hamilton_terms_match(what, connection, model, rng);
                                     });
}

// lem:horizontal-differential (hor-diff-curve): d^nabla F(w) = d/de F(Gamma(c)_0^e X) for the
// curve c(e) = g exp(e w) (left) or exp(e w) g (right), whose trivialised velocity is the constant
// w. The transport of a vector is P(e) = Texp(-int_0^e nabla_w) (cor-parr, by the generic ordered
// exponential; backwards for e < 0 along -w), of a covector P(e)^{-T} (eq:parr-left-dual). So
// d/de l(c(e), P(e) v) is the horizontal term of (EL-Lie) along w, and d/de h(c(e), P(e)^{-T} mu)
// that of (Hamilton-Lie). Tolerance: fourth-order difference of exact transports, 1e-9.
TEST(ConnectionTerms, HorizontalDifferentialIsTheDerivativeAlongParallelTransport) {
  std::mt19937 rng(kSeed + 63);
  using Tangent = groups::SO3::Tangent;
  const mechanics::SO3Oscillator l(kInertia);
  const mechanics::SO3OscillatorHamiltonian h(kInertia);
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    const auto lr = mechanics::right_reduced_lagrangian<groups::SO3>(l);
    const auto hr = mechanics::right_reduced_hamiltonian<groups::SO3>(h);
    for (const auto& named : connections_on<groups::SO3>(side)) {
      const std::string& name = named.first;
      const auto& connection = named.second;  // not a structured binding: the lambdas below capture it
      const ExpChart<groups::SO3> chart{side, random_element<groups::SO3>(rng, 0.8)};
      const Tangent v = random_tangent<groups::SO3>(rng, 1.5), w = random_tangent<groups::SO3>(rng);
      const Tangent mu = random_tangent<groups::SO3>(rng, 1.5);
      const auto transport = [&](double e) -> Eigen::Matrix3d {
        if (e == 0) return Eigen::Matrix3d::Identity();
        const Tangent along = e > 0 ? w : Tangent(-w);
        return transport::transport_operator<groups::SO3>(connection, [&](double) { return along; }, 0.0, std::abs(e), 4,
                                                          transport::TransportMethod::Magnus4);
      };
      const bool left = side == groups::Side::Left;
      const double dl = derivative(
          [&](double e) {
            const Tangent moved = transport(e) * v;
            return left ? l.value(0.0, chart.point(Tangent(e * w)), moved) : lr.value(0.0, chart.point(Tangent(e * w)), moved);
          },
          1e-3);
      const double dh = derivative(
          [&](double e) {
            const Tangent moved = transport(e).transpose().lu().solve(mu);
            return left ? h.value(0.0, chart.point(Tangent(e * w)), moved) : hr.value(0.0, chart.point(Tangent(e * w)), moved);
          },
          1e-3);
      const Tangent zeta = left ? l.group_gradient(0.0, chart.g, v) : lr.group_gradient(0.0, chart.g, v);
      const Tangent momentum = left ? l.momentum(0.0, chart.g, v) : lr.momentum(0.0, chart.g, v);
      const Tangent zeta_h = left ? h.group_gradient(0.0, chart.g, mu) : hr.group_gradient(0.0, chart.g, mu);
      const Tangent velocity = left ? h.velocity(0.0, chart.g, mu) : hr.velocity(0.0, chart.g, mu);
      const auto el = mechanics::euler_lagrange_terms<groups::SO3>(connection, v, momentum, zeta);
      const auto he = mechanics::hamilton_terms<groups::SO3>(connection, velocity, mu, zeta_h);
      EXPECT_NEAR(el.horizontal.dot(w), dl, 1e-9) << to_string(side) << ' ' << name;
      EXPECT_NEAR(he.horizontal.dot(w), dh, 1e-9) << to_string(side) << ' ' << name;
    }
  }
}

// The chain rules (chain-rule) on TG and (chain-rule-2) on T*G, trivialised: for a (non-invariant)
// vector field V = g f(g) and a covector field with trivialisation m(g),
//   d(l o V)(w) = horizontal(EL) . w + mu . (d f(w) + nabla_w f)   (mu = dl/dv at v = f(g)),
//   d(h o m)(w) = horizontal(HE) . w + (d m(w) - nabla*_w m) . v   (v = dh/dmu at mu = m(g)),
// with d f(w) = d/de f(g exp(e w)). The left sides by differences of l(g, f(g)) and h(g, m(g)); a
// wrong sign of a connection part of `horizontal` fails by O(1). Tolerance as kTermTolerance.
TEST(ConnectionTerms, ChainRules) {
  std::mt19937 rng(kSeed + 64);
  using Tangent = groups::SO3::Tangent;
  const mechanics::SO3Oscillator l(kInertia);
  const mechanics::SO3OscillatorHamiltonian h(kInertia);
  const Eigen::Matrix<double, 3, 9> m = random_vector<Eigen::Matrix<double, 27, 1>>(rng, 1.0).reshaped(3, 9);
  const auto field = [&](const groups::SO3::Element& g) -> Tangent { return (m * g.reshaped()).array().sin().matrix(); };
  const auto connection = non_cartan_connection<groups::SO3>(groups::Side::Left);
  const groups::SO3::Element g = random_element<groups::SO3>(rng);
  const Tangent w = random_tangent<groups::SO3>(rng);
  const auto along = [&](double e) { return groups::SO3::compose(g, groups::SO3::exp(Tangent(e * w))); };
  const Tangent f = field(g), df = derivative([&](double e) { return field(along(e)); }, 1e-3);
  const double d_lagrangian = derivative([&](double e) { return l.value(0.0, along(e), field(along(e))); }, 1e-3);
  const auto el = mechanics::euler_lagrange_terms<groups::SO3>(connection, f, l.momentum(0.0, g, f), l.group_gradient(0.0, g, f));
  const Tangent mu = l.momentum(0.0, g, f);
  EXPECT_NEAR(d_lagrangian, el.horizontal.dot(w) + mu.dot(connection.covariant_derivative(w, f, df)), kTermTolerance);
  const double d_hamiltonian = derivative([&](double e) { return h.value(0.0, along(e), field(along(e))); }, 1e-3);
  const Tangent v = h.velocity(0.0, g, f);
  const auto he = mechanics::hamilton_terms<groups::SO3>(connection, v, f, h.group_gradient(0.0, g, f));
  EXPECT_NEAR(d_hamiltonian, he.horizontal.dot(w) + connection.covariant_derivative_dual(w, f, df).dot(v), kTermTolerance);
  EXPECT_GT(std::abs(mu.dot(connection.nabla(w, f))), 0.05);  // the connection parts are not negligible
}

// The covariant derivative of a covector along a curve, in coordinates (D/dt p)_i = p_i' -
// Gamma^k_ji x'^j p_k with p_i(t) = mu(t) . F_i(x(t)), equals its trivialisation mu' - nabla*_v mu
// (eq:cov-curve-left-dual): the term `covariant` above is its connection part, and here the
// derivative of the coordinate components along a curve x(t) = t v + t^2 a is checked too.
TEST(ConnectionTerms, CovariantDerivativeOfACovectorAlongACurve) {
  std::mt19937 rng(kSeed + 62);
  using Tangent = groups::SO3::Tangent;
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    const auto connection = non_cartan_connection<groups::SO3>(side);
    const ExpChart<groups::SO3> chart{side, random_element<groups::SO3>(rng, 0.8)};
    const auto gamma = chart.christoffel(connection);
    const Tangent v = random_tangent<groups::SO3>(rng), a = random_tangent<groups::SO3>(rng);
    const Tangent mu0 = random_tangent<groups::SO3>(rng), mu1 = random_tangent<groups::SO3>(rng);
    const Tangent pdot = derivative(
        [&](double t) -> Tangent {
          return chart.frame(Tangent(t * v + t * t * a)).transpose() * Tangent(mu0 + t * mu1);
        },
        ExpChart<groups::SO3>::kStep);
    const Tangent coordinate = pdot + coordinate_terms<groups::SO3>(gamma, v, mu0).covariant;
    const Tangent trivialised = connection.covariant_derivative_dual(v, mu0, mu1);
    EXPECT_LE(max_abs_diff(coordinate, trivialised), kTermTolerance) << to_string(side);
    EXPECT_GT((trivialised - mu1).norm(), 0.1);  // the connection part is not negligible
  }
}

// (Hamilton-Lie) with each connection reproduces eq:LP-left / eq:LP-right: the same RKMK4 steps,
// momentum rates equal up to the rounding of the cancelling terms (the tolerance argument of
// test_euler_lagrange.cpp: measured <= 2e-14, allowed 1e-11).
template <groups::LieGroup G, mechanics::ReducedHamiltonian<G> H>
void expect_lie_poisson(const std::string& model, const H& h, groups::Side side, const groups::ElementOf<G>& g0,
                        const groups::CovectorOf<G>& mu0) {
  const auto reference = mechanics::lie_poisson<G>(side, h, g0, mu0, 10.0, 400);
  for (const auto& [name, connection] : connections_on<G>(side)) {
    expect_same_trajectory<G>(model + ", " + std::string(to_string(side)) + ", " + name, reference,
                              mechanics::hamilton<G>(connection, h, g0, mu0, 10.0, 400), 1e-11);
  }
}

TEST(Hamilton, ConnectionTermsCancelToLiePoisson) {
  const groups::SO3::Element g0 = groups::SO3::exp(groups::SO3::Tangent(0.3, -0.5, 0.4));
  const groups::SO3::Tangent mu0(1.1, -0.8, 0.9);
  const mechanics::SO3OscillatorHamiltonian oscillator(kInertia);
  expect_lie_poisson<groups::SO3>("SO(3) oscillator", oscillator, groups::Side::Left, g0, mu0);
  expect_lie_poisson<groups::SO3>("SO(3) oscillator", mechanics::right_reduced_hamiltonian<groups::SO3>(oscillator),
                                  groups::Side::Right, g0, groups::SO3::Tangent(g0 * mu0));
  const groups::Heisenberg::Element h0(0.3, -0.5, 0.2);
  const auto h3 = mechanics::h3_oscillator_hamiltonian();
  expect_lie_poisson<groups::Heisenberg>("H3 oscillator", h3, groups::Side::Left, h0, groups::Heisenberg::Tangent(0.4, 0.7, -0.3));
}

// Hamilton's equations and the Euler–Lagrange equation with the same connection describe the same
// motion through the Legendre transform mu = dl/dv: the two integrators take the same steps in
// (g, mu), so their trajectories agree to rounding, here under the non-Cartan connection whose
// terms do not vanish individually.
TEST(Hamilton, LegendreTransformOfEulerLagrange) {
  const groups::SO3::Element g0 = groups::SO3::exp(groups::SO3::Tangent(-0.2, 0.6, 0.1));
  const groups::SO3::Tangent v0(0.7, 0.4, -0.9);
  const mechanics::SO3Oscillator l(kInertia);
  const mechanics::SO3OscillatorHamiltonian h(kInertia);
  const auto connection = non_cartan_connection<groups::SO3>(groups::Side::Left);
  const auto lagrangian = mechanics::euler_lagrange<groups::SO3>(connection, l, g0, v0, 8.0, 320);
  const auto hamiltonian = mechanics::hamilton<groups::SO3>(connection, h, g0, l.momentum(0.0, g0, v0), 8.0, 320);
  EXPECT_LE(max_group_difference(lagrangian, hamiltonian), 1e-11);
  EXPECT_LE(max_momentum_difference(lagrangian, hamiltonian), 1e-11);
  // Energy h(g, mu) is conserved by the exact flow; RKMK4 with h = 1/40 keeps it to O(h^4) ~ 1e-6.
  const double h0 = h.value(0.0, g0, hamiltonian.mu.front());
  EXPECT_LE(max_drift<groups::SO3>(hamiltonian, [&](std::size_t k) { return h.value(0.0, hamiltonian.g[k], hamiltonian.mu[k]); }),
            1e-5 * std::max(1.0, std::abs(h0)));
}

TEST(Hamilton, RejectsBadInput) {
  const mechanics::SO3OscillatorHamiltonian h(kInertia);
  const auto connection = non_cartan_connection<groups::SO3>(groups::Side::Left);
  expect_invalid([&] { mechanics::hamilton<groups::SO3>(connection, h, groups::SO3::identity(), groups::SO3::Tangent(1, 0, 0), -1.0, 10); },
                 {"hamilton", "T", "-1"});
  expect_invalid(
      [&] {
        mechanics::hamilton<groups::SO3>(connection, h, groups::SO3::identity(),
                                         groups::SO3::Tangent(std::nan(""), 0, 0), 1.0, 10);
      },
      {"hamilton", "mu0"});
}

}  // namespace
}  // namespace cartan::testing
