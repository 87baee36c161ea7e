// The global Hamilton equations with a connection (eq:HE-1, prop:hamilton-principle-phase) on
// manifolds that are not groups (kernels/manifold/hamilton.hpp): the sphere in its stereographic chart
// under four connections (Levi-Civita; with torsion; with another symmetric part; both) and R^2
// with constant connections (torsion and curvature; metric with torsion).
//   (a) each term against its definition (finite differences, parallel transport);
//   (b) the Legendre transform of the general Euler–Lagrange solution (kernels/manifold/scheme.hpp) solves
//       eq:HE-1 (sphere: Levi-Civita; R^2: metric with torsion), at the scheme's order 2;
//   (c) H is conserved at RK4's order;
//   (d) solutions make the phase-space action stationary (prop:hamilton-principle-phase);
//   (e) the solution does not depend on the connection (the remark after the proposition), while
//       each term does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>

#include "cartan/kernels/manifold/scheme.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "kernels/manifold/hamilton_cases.hpp"
#include "mechanics/mechanics_support.hpp"

namespace cartan::testing {
namespace {

using general::HamiltonTerms;
using general::HamiltonTrajectory;
using Vec2 = Eigen::Vector2d;

const Eigen::Matrix2d kMass = (Eigen::Matrix2d() << 1.5, 0.3, 0.3, 0.8).finished();

/// Gamma^k_ij of a chart or constant connection, from the instance's own coefficient arrays
/// (entry [i](k, j)), independent of christoffel().
template <class M>
auto coefficients_at(const M& manifold, const Vec2& q) {
  if constexpr (requires { manifold.coefficients(q); }) {
    return manifold.coefficients(q);
  } else {
    return manifold.coefficients();
  }
}

// (a) Tolerances: fourth-order differences with step 1e-3 of O(1) smooth functions: truncation
// ~1e-12, rounding ~1e-16 / 1e-3 = 1e-13; the chart's transport over s <= 2e-3 is RK4 with
// (a / n)^5 ~ 1e-17 relative error. 1e-9 is far above both and far below the O(0.1-1) terms
// (a wrong sign or a transposed Gamma fails by > 1e-2).
constexpr double kStep = 1e-3;
constexpr double kTermTolerance = 1e-9;

template <class M, class H>
void expect_terms_are_their_definitions(const std::string& what, const M& manifold, const H& hamiltonian, const Vec2& q,
                                        const Vec2& p, std::mt19937& rng) {
  const HamiltonTerms<M> terms = general::hamilton_terms(manifold, hamiltonian, 0.0, q, p);
  const auto value = [&](const Vec2& x, const Vec2& y) { return hamiltonian.value(0.0, x, y); };
  Vec2 dH_dp, dH_dq, horizontal_by_transport;
  for (int i = 0; i < 2; ++i) {
    const Vec2 e = Vec2::Unit(i);
    dH_dp[i] = derivative([&](double s) { return value(q, Vec2(p + s * e)); }, kStep);
    dH_dq[i] = derivative([&](double s) { return value(Vec2(q + s * e), p); }, kStep);
    // lem:horizontal-differential: d/ds H along the transport of p (inverse transpose of the
    // vector transport, pairings preserved) along the line q + s e_i.
    horizontal_by_transport[i] = derivative(
        [&](double s) {
          const Eigen::Matrix2d P = manifold.transport_along_step(q, Vec2(s * e));
          return value(Vec2(q + s * e), Vec2(P.transpose().lu().solve(p)));
        },
        kStep);
  }
  EXPECT_LE(max_abs_diff(terms.velocity, dH_dp), kTermTolerance) << what << " (eq:vert-grad)";
  EXPECT_LE(max_abs_diff(hamiltonian.point_gradient(0.0, q, p), dH_dq), kTermTolerance) << what << " (dH/dq)";
  EXPECT_LE(max_abs_diff(terms.horizontal, horizontal_by_transport), kTermTolerance) << what << " (eq:hor-diff-2)";

  // D/dt p along the curve q + s q' with p(s) = p + s w: d/ds P_s^T p(s) at 0 = p' + covariant.
  const Vec2 w = random_vector<Vec2>(rng, 1.0);
  const Vec2 pulled_back = derivative(
      [&](double s) -> Vec2 {
        return manifold.transport_along_step(q, Vec2(s * terms.velocity)).transpose() * Vec2(p + s * w);
      },
      kStep);
  EXPECT_LE(max_abs_diff(Vec2(w + terms.covariant), pulled_back), kTermTolerance) << what << " (D/dt p)";

  // p(i_{q'} T)_i = p_k (Gamma^k_ji - Gamma^k_ij) q'^j from the coefficient arrays.
  const auto c = coefficients_at(manifold, q);
  Vec2 torsion = Vec2::Zero();
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) torsion[i] += p.dot(c[j].col(i) - c[i].col(j)) * terms.velocity[j];
  }
  EXPECT_LE(max_abs_diff(terms.torsion, torsion), kTermTolerance) << what << " (torsion)";
  std::cout << "[ measured ] " << what << ": |covariant| = " << terms.covariant.norm()
            << ", |torsion| = " << terms.torsion.norm() << ", |horizontal - dH/dq| = " << (terms.horizontal - dH_dq).norm()
            << '\n';
}

TEST(GeneralHamilton, TermsAreTheirDefinitions) {
  std::mt19937 rng(kSeed + 130);
  const auto sphere_h = sphere_pendulum_hamiltonian(1.0);
  for (const auto& [name, chart] : sphere_connections()) {
    for (int trial = 0; trial < 3; ++trial) {
      expect_terms_are_their_definitions("sphere, " + name, chart, sphere_h, random_vector<Vec2>(rng, 0.8),
                                         random_vector<Vec2>(rng, 1.5), rng);
    }
  }
  const auto flat_h = euclidean_hamiltonian(kMass);
  for (const Euclidean<2>& m : {skew_euclidean(), metric_torsion_euclidean()}) {
    expect_terms_are_their_definitions("R^2", m, flat_h, random_vector<Vec2>(rng, 1.0), random_vector<Vec2>(rng, 1.5), rng);
  }
}

/// The stereographic chart carries the quadric's connection and metric (quadric.hpp): with
/// phi = from_stereographic, d_i d_j phi + Gamma^Q(d_i phi, d_j phi) = Gamma^k_ij d_k phi and
/// d phi^T J d phi = g. Nested fourth-order differences, step 1e-3, at |x| <= 0.57 (on H^2 the
/// derivatives of phi grow like (1 - |x|^2)^-k; here 1 - |x|^2 >= 0.68): truncation ~1e-12
/// |phi^(6)| ~ 1e-9, rounding 1e-16 / 1e-6 = 1e-10; tolerance 1e-8.
template <int K>
void expect_stereographic_chart_is_the_quadric(std::mt19937& rng) {
  using Quadric = manifolds::Quadric<K>;
  const Chart<2> chart = manifolds::stereographic_chart<K>();
  const Vec2 x = random_vector<Vec2>(rng, 0.4);
  const auto phi = [](const Vec2& y) { return manifolds::from_stereographic<K>(y); };
  const auto d_phi = [&](const Vec2& y, int i) {
    return derivative([&](double s) -> Eigen::Vector3d { return phi(Vec2(y + s * Vec2::Unit(i))); }, kStep);
  };
  const auto gamma = chart.coefficients(x);
  Eigen::Matrix<double, 3, 2> jacobian;
  for (int i = 0; i < 2; ++i) jacobian.col(i) = d_phi(x, i);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const Eigen::Vector3d second = derivative([&](double s) -> Eigen::Vector3d { return d_phi(Vec2(x + s * Vec2::Unit(i)), j); }, kStep);
      const Eigen::Vector3d ambient = second + Quadric::christoffel(phi(x), jacobian.col(i), jacobian.col(j));
      EXPECT_LE(max_abs_diff(ambient, jacobian * gamma[i].col(j)), 1e-8) << Quadric::name() << " Gamma_" << i << j;
    }
  }
  EXPECT_LE(max_abs_diff(Eigen::Matrix2d(jacobian.transpose() * Quadric::metric(phi(x)) * jacobian), *chart.metric(x)), 1e-8);
  EXPECT_LE(max_abs_diff(manifolds::stereographic(phi(x)), x), 1e-14);
}

TEST(GeneralHamilton, StereographicChartIsTheQuadric) {
  std::mt19937 rng(kSeed + 131);
  expect_stereographic_chart_is_the_quadric<1>(rng);
  expect_stereographic_chart_is_the_quadric<-1>(rng);
}

/// max over nodes of |q_a - q_b| + |p_a - p_b|.
template <class A, class B>
double max_phase_difference(const HamiltonTrajectory<A>& a, const HamiltonTrajectory<B>& b) {
  double out = 0;
  for (std::size_t k = 0; k < a.q.size(); ++k) out = std::max(out, (a.q[k] - b.q[k]).norm() + (a.p[k] - b.p[k]).norm());
  return out;
}

/// The general Euler–Lagrange solution (the transported-velocity principle of kernels/manifold/scheme.hpp,
/// order 2, from q0 with velocity u0 and Xi0 = 0) as chart points and momenta: the node's
/// velocity is E v, mapped by `chart_of` to (chart point, chart velocity), and p = g q'.
/// For l = 1/2 |v|^2 - V and a metric connection (orthonormal frames), |v| = |q'|, so the
/// transported principle is the classical one (docs/paper-notes.md#general-metric-connections) and
/// the curvature term vanishes (Xi symmetric, R_ij antisymmetric in an orthonormal frame):
/// the Legendre transform of its solution solves eq:HE-1.
template <class M, class ChartOf, class H>
HamiltonTrajectory<Chart<2>> legendre_of_general_solution(const M& manifold, const general::KineticPotential<M>& lagrangian,
                                                          const manifolds::PointOf<M>& q0, const manifolds::VectorOf<M>& u0,
                                                          double T, int N, const ChartOf& chart_of, const H& hamiltonian) {
  const general::GeneralProblem<M, general::KineticPotential<M>> problem{manifold, lagrangian, T, N, q0, q0, std::nullopt};
  const general::GeneralScheme<M, general::KineticPotential<M>> scheme(problem, general::SchemeOrder::Second);
  const manifolds::FrameOf<M> frame0 = problem.initial_frame();
  general::GeneralNode<M> node = scheme.initial(manifolds::dual_frame<M>(frame0) * u0, manifolds::ComponentMatrixOf<M>::Zero()), next;
  HamiltonTrajectory<Chart<2>> out;
  for (int k = 0;; ++k) {
    const auto [x, xdot] = chart_of(node.q, manifolds::VectorOf<M>(node.frame * node.v));
    out.t.push_back(node.t), out.q.push_back(x), out.p.push_back(hamiltonian.momentum(x, xdot));
    if (k == N) break;
    scheme.step(node, next);
    node = next;
  }
  return out;
}

// (b) The general scheme has order 2 and RK4 order 4, so at the same N the difference is the
// scheme's error C h^2: measured orders within 0.3 of 2 (a wrong sign or term leaves an O(1)
// difference, order 0).
template <class Manifold, class ChartOf>
void expect_legendre_equivalence(const std::string& what, const Manifold& manifold, const general::KineticPotential<Manifold>& l,
                                 const manifolds::PointOf<Manifold>& q0, const manifolds::VectorOf<Manifold>& u0,
                                 const auto& chart, const auto& hamiltonian, const ChartOf& chart_of) {
  constexpr double T = 2.0;
  std::vector<double> errors;
  for (int N : {50, 100, 200}) {
    const auto lagrangian_side = legendre_of_general_solution(manifold, l, q0, u0, T, N, chart_of, hamiltonian);
    const auto hamilton_side = general::hamilton(chart, hamiltonian, lagrangian_side.q[0], lagrangian_side.p[0], T, N);
    errors.push_back(max_phase_difference(lagrangian_side, hamilton_side));
  }
  for (double order : measured_orders(what + ": Legendre(general EL) - HE-1", errors)) EXPECT_NEAR(order, 2.0, 0.3) << what;
}

TEST(GeneralHamilton, LegendreTransformOfTheGeneralEulerLagrangeSolution) {
  // The spherical pendulum: kernels/manifold/ on the embedded Sphere, eq:HE-1 in its stereographic chart.
  constexpr double G = 1.0;
  const auto pendulum = general::KineticPotential<manifolds::Sphere>::with_linear_potential(Eigen::Matrix2d::Identity(),
                                                                                            Eigen::Vector3d(0, 0, -G));
  const Eigen::Vector3d q0 = manifolds::sphere_point(Eigen::Vector3d(0.3, -0.2, 1.0));
  const Eigen::Vector3d u0 = manifolds::Sphere::project_tangent(q0, Eigen::Vector3d(0.6, 0.9, 0.1));
  const auto sphere_to_chart = [](const Eigen::Vector3d& q, const Eigen::Vector3d& u) {
    return std::pair<Vec2, Vec2>(manifolds::stereographic(q), manifolds::stereographic_velocity(q, u));
  };
  expect_legendre_equivalence("sphere", manifolds::Sphere(), pendulum, q0, u0, manifolds::stereographic_chart<1>(),
                              sphere_pendulum_hamiltonian(G), sphere_to_chart);

  // R^2 with a metric connection with torsion, on both sides.
  const Euclidean<2> torsion = metric_torsion_euclidean();
  const general::KineticPotential<Euclidean<2>> particle(Eigen::Matrix2d::Identity(), anharmonic, anharmonic_gradient);
  const auto identity = [](const Vec2& q, const Vec2& u) { return std::pair<Vec2, Vec2>(q, u); };
  expect_legendre_equivalence("R^2 with torsion", torsion, particle, Vec2(0.5, -0.3), Vec2(0.4, 0.9), torsion,
                              euclidean_hamiltonian(Eigen::Matrix2d::Identity()), identity);
}

/// max_k |H(q_k, p_k) - H(q_0, p_0)|.
template <class M, class H>
double energy_drift(const H& hamiltonian, const HamiltonTrajectory<M>& x) {
  double drift = 0;
  for (std::size_t k = 0; k < x.q.size(); ++k) {
    drift = std::max(drift, std::abs(hamiltonian.value(0.0, x.q[k], x.p[k]) - hamiltonian.value(0.0, x.q[0], x.p[0])));
  }
  return drift;
}

// (c) RK4 is not symplectic: H drifts by its global error, C T h^4 with C set by fifth
// derivatives of the flow (frequencies ~1 here). Orders >= 3.7 when h halves, and the drift at
// the finest h = 0.025 below T h^4 / 5! = 3.3e-8 (the local error's Taylor coefficient 1/5! with
// frequencies and amplitudes <= 1; measured: 2e-9 and 3e-9). A term with a wrong sign breaks
// conservation at O(1).
template <class M, class H>
void expect_energy_conserved(const std::string& what, const M& manifold, const H& hamiltonian, const Vec2& q0, const Vec2& p0) {
  constexpr double T = 10.0;
  std::vector<double> drifts;
  for (int N : {100, 200, 400}) drifts.push_back(energy_drift(hamiltonian, general::hamilton(manifold, hamiltonian, q0, p0, T, N)));
  for (double order : measured_orders(what + ": energy drift", drifts)) EXPECT_GE(order, 3.7) << what;
  EXPECT_LE(drifts.back(), T * std::pow(T / 400, 4) / 120) << what;
}

TEST(GeneralHamilton, EnergyIsConserved) {
  const auto connections = sphere_connections();
  expect_energy_conserved("sphere, " + connections[3].first, connections[3].second, sphere_pendulum_hamiltonian(1.0),
                          Vec2(0.2, -0.1), Vec2(0.9, 1.2));
  expect_energy_conserved("R^2, torsion and curvature", skew_euclidean(), euclidean_hamiltonian(kMass), Vec2(0.5, -0.3),
                          Vec2(0.4, 0.9));
}

// (d) The first variation of the midpoint phase-space action S_h (general::phase_space_action)
// along delta q (zero at both ends) and any delta p is, at a solution, the midpoint rule applied
// to the vanishing continuous variation: O(h^2) (plus RK4's O(h^4)). dS/de by a fourth-order
// difference in e (step 1e-3, error ~1e-12). Orders within 0.3 of 2; the trajectory of another
// Hamiltonian (V scaled by 1.2) is not stationary (derivative >= 1e-2, the O(1) of a
// non-solution, not falling with h).
template <class M, class H>
double action_derivative(const H& hamiltonian, const HamiltonTrajectory<M>& x) {
  const double T = x.t.back();
  return derivative(
      [&](double e) {
        HamiltonTrajectory<M> varied = x;
        for (std::size_t k = 0; k < x.t.size(); ++k) {
          const double t = x.t[k];
          varied.q[k] += e * Vec2(std::sin(std::numbers::pi * t / T), 0.5 * std::sin(2 * std::numbers::pi * t / T));
          varied.p[k] += e * Vec2(std::cos(t), 0.3 * t);
        }
        return general::phase_space_action<M>(hamiltonian, varied);
      },
      kStep);
}

template <class M, class H>
void expect_action_stationary(const std::string& what, const M& manifold, const H& hamiltonian, const H& other,
                              const Vec2& q0, const Vec2& p0) {
  constexpr double T = 2.0;
  std::vector<double> derivatives;
  for (int N : {50, 100, 200}) derivatives.push_back(std::abs(action_derivative<M>(hamiltonian, general::hamilton(manifold, hamiltonian, q0, p0, T, N))));
  for (double order : measured_orders(what + ": dS/de at solutions", derivatives)) EXPECT_NEAR(order, 2.0, 0.3) << what;
  const double off = std::abs(action_derivative<M>(hamiltonian, general::hamilton(manifold, other, q0, p0, T, 200)));
  std::cout << "[ measured ] " << what << ": dS/de at another Hamiltonian's solution " << off << '\n';
  EXPECT_GE(off, 1e-2) << what;
}

TEST(GeneralHamilton, PhaseSpaceActionIsStationaryAtSolutions) {
  const auto connections = sphere_connections();
  expect_action_stationary("sphere, " + connections[1].first, connections[1].second, sphere_pendulum_hamiltonian(1.0),
                           sphere_pendulum_hamiltonian(1.2), Vec2(0.2, -0.1), Vec2(0.9, 1.2));
  const auto scaled = general::KineticPotentialHamiltonian<Euclidean<2>>::constant(
      kMass, [](const Vec2& q) { return 1.2 * anharmonic(q); }, [](const Vec2& q) { return Vec2(1.2 * anharmonic_gradient(q)); });
  expect_action_stationary("R^2, torsion and curvature", skew_euclidean(), euclidean_hamiltonian(kMass), scaled,
                           Vec2(0.5, -0.3), Vec2(0.4, 0.9));
}

// (e) The paper (after prop:hamilton-principle-phase): in any chart eq:HE-1 reduces to
// q' = dH/dp, p' = -dH/dq "regardless of the linear connection used". So connections with the
// same spray and different torsion, the same torsion and different sprays, or neither, give the
// same solution: the terms cancel exactly, so the trajectories agree to rounding (1e-12 after
// 400 steps), while the terms themselves differ by O(0.1-1) between connections.
template <class M, class H>
void expect_independent_of_connection(const std::string& what, const std::vector<std::pair<std::string, M>>& connections,
                                      const H& hamiltonian, const Vec2& q0, const Vec2& p0) {
  const auto& [reference_name, reference] = connections.front();
  const auto reference_path = general::hamilton(reference, hamiltonian, q0, p0, 4.0, 400);
  const HamiltonTerms<M> reference_terms = general::hamilton_terms(reference, hamiltonian, 0.0, q0, p0);
  EXPECT_LE(max_abs_diff(reference_terms.momentum_rate(), Vec2(-hamiltonian.point_gradient(0.0, q0, p0))), 1e-14);
  for (std::size_t c = 1; c < connections.size(); ++c) {
    const std::string label = what + ", " + connections[c].first + " vs " + reference_name;
    const double difference = max_phase_difference(reference_path, general::hamilton(connections[c].second, hamiltonian, q0, p0, 4.0, 400));
    const HamiltonTerms<M> terms = general::hamilton_terms(connections[c].second, hamiltonian, 0.0, q0, p0);
    const double term_change = std::max({(terms.covariant - reference_terms.covariant).norm(),
                                         (terms.torsion - reference_terms.torsion).norm(),
                                         (terms.horizontal - reference_terms.horizontal).norm()});
    std::cout << "[ measured ] " << label << ": trajectories differ by " << difference << ", terms by " << term_change << '\n';
    EXPECT_LE(difference, 1e-12) << label;
    EXPECT_GE(term_change, 0.1) << label;
  }
}

TEST(GeneralHamilton, SolutionDoesNotDependOnTheConnection) {
  expect_independent_of_connection("sphere", sphere_connections(), sphere_pendulum_hamiltonian(1.0), Vec2(0.2, -0.1),
                                   Vec2(0.9, 1.2));
  const std::vector<std::pair<std::string, Euclidean<2>>> flat{
      {"flat", Euclidean<2>()}, {"torsion and curvature", skew_euclidean()}, {"metric with torsion", metric_torsion_euclidean()}};
  expect_independent_of_connection("R^2", flat, euclidean_hamiltonian(kMass), Vec2(0.5, -0.3), Vec2(0.4, 0.9));
}

TEST(GeneralHamilton, RejectsBadInput) {
  const Euclidean<2> m;
  const auto h = euclidean_hamiltonian(kMass);
  expect_invalid([&] { general::hamilton(m, h, Vec2(0, 0), Vec2(1, 0), -1.0, 10); }, {"T", "must be positive"});
  expect_invalid([&] { general::hamilton(m, h, Vec2(0, 0), Vec2(1, 0), 1.0, 0); }, {"steps"});
  expect_invalid([&] { general::hamilton(m, h, Vec2(0, 0), Vec2(std::numeric_limits<double>::quiet_NaN(), 0), 1.0, 10); }, {"p0"});
  expect_invalid([&] { general::hamilton(manifolds::stereographic_chart<-1>(), h, Vec2(1.5, 0), Vec2(1, 0), 1.0, 10); },
                 {"q0", "outside the chart"});
}

}  // namespace
}  // namespace cartan::testing
