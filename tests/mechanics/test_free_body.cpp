// The free bodies on SE(2) and SE(3) (mechanics/free_body.hpp) through the library's solve
// (compiled once in src/methods/lie_group/solve_se*_free_body.cpp), against what does not depend on the
// solver: a relative equilibrium in closed form (g(t) = exp(t v) when ad*_v (I v) = 0), the left
// Euler-Poincare equation at lambda = 0 (paper-notes "Classical limits"), energy conservation,
// the Hamiltonians as Legendre transforms (with Lie-Poisson against Euler-Poincare), and the
// inertia validation.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "cartan/kernels/lie_group/verify.hpp"
#include "cartan/mechanics/euler_poincare.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/lie_poisson.hpp"
#include "cartan/methods/lie_group/solve.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

static_assert(mechanics::ReducedLagrangian<mechanics::SE2FreeBody, groups::SE2>);
static_assert(mechanics::ReducedLagrangian<mechanics::SE3FreeBody, groups::SE3>);
static_assert(mechanics::ReducedHamiltonian<mechanics::SE2FreeBodyHamiltonian, groups::SE2>);
static_assert(mechanics::ReducedHamiltonian<mechanics::SE3FreeBodyHamiltonian, groups::SE3>);

/// A full symmetric positive-definite inertia of size n: diag(1..n) plus a small symmetric coupling.
template <int n>
Eigen::Matrix<double, n, n> coupled_inertia() {
  Eigen::Matrix<double, n, n> inertia = Eigen::Matrix<double, n, n>::Zero();
  for (int i = 0; i < n; ++i) {
    inertia(i, i) = 1.0 + i;
    if (i + 1 < n) inertia(i, i + 1) = inertia(i + 1, i) = 0.2;
  }
  return inertia;
}

template <groups::LieGroup G, class L>
transported::TransportedSolution<G> solve_or_fail(const transported::TransportedProblem<G, L>& problem) {
  transported::SolveOptions options;
  options.order = transported::SchemeOrder::Second;
  options.tol = 1e-12;
  const auto s = transported::solve(problem, options);
  EXPECT_TRUE(s.converged()) << s.message;
  return s;
}

// v with ad*_v (I v) = 0 (an eigenvector of a diagonal inertia along a coordinate axis, or a
// screw with equal translational and rotational eigenvalue): g(t) = exp(t v) and the transported
// velocity stays v, for every lambda (the velocity of a one-parameter subgroup is parallel for
// every Cartan-Schouten connection). The scheme reproduces it to rounding.
template <groups::LieGroup G, class L>
void expect_relative_equilibrium(const L& body, const groups::TangentOf<G>& v) {
  const double T = 2.0;
  for (double lambda : {0.0, 0.5, 1.0, -0.5}) {
    const transported::TransportedProblem<G, L> problem{body, lambda, T, 100, G::identity(), G::exp(T * v)};
    const auto s = solve_or_fail(problem);
    ASSERT_EQ(s.trajectory.t.size(), 101u);
    EXPECT_LE((s.v0 - v).norm(), 1e-9) << "lambda " << lambda;
    for (std::size_t k = 0; k < s.trajectory.t.size(); ++k) {
      EXPECT_LE(max_abs_diff(s.trajectory.g[k], G::exp(s.trajectory.t[k] * v)), 1e-9) << "lambda " << lambda << " k " << k;
      EXPECT_LE((s.trajectory.v[k] - v).norm(), 1e-9) << "lambda " << lambda << " k " << k;
    }
  }
}

TEST(FreeBody, SE2RotationAndTranslationAreRelativeEquilibria) {
  const mechanics::SE2FreeBody body(Eigen::Vector3d(2, 3, 0.5).asDiagonal().toDenseMatrix());
  expect_relative_equilibrium<groups::SE2>(body, Eigen::Vector3d(0.8, 0, 0));
  expect_relative_equilibrium<groups::SE2>(body, Eigen::Vector3d(0, 0, 1.1));
}

TEST(FreeBody, SE3ScrewMotionIsARelativeEquilibrium) {
  Eigen::Matrix<double, 6, 1> diagonal;
  diagonal << 1, 2, 3, 4, 5, 3;  // translation z and rotation z share the eigenvalue 3
  const mechanics::SE3FreeBody body(diagonal.asDiagonal().toDenseMatrix());
  Eigen::Matrix<double, 6, 1> screw;
  screw << 0, 0, 0.4, 0, 0, 0.9;
  expect_relative_equilibrium<groups::SE3>(body, screw);
}

// lambda = 0: the transported free body follows the left Euler-Poincare equation (integrated here
// by RKMK4, independently of the scheme) from the solver's v0, to the order-2 scheme's O(h^2).
template <groups::LieGroup G, class L>
void expect_euler_poincare_at_lambda_zero(const L& body, const groups::ElementOf<G>& gT) {
  const double T = 1.5;
  double previous = 0;
  for (int N : {100, 200}) {
    const transported::TransportedProblem<G, L> problem{body, 0.0, T, N, G::identity(), gT};
    const auto s = solve_or_fail(problem);
    const auto ep = mechanics::euler_poincare<G>(groups::Side::Left, body, G::identity(), s.v0, T, 2000);
    const double miss = G::log(G::compose(G::inverse(gT), ep.g.back())).norm();
    EXPECT_LE(miss, 5.0 / (N * N)) << "N " << N;
    if (N == 200) {
      EXPECT_LE(miss, previous / 3) << "second order: " << previous << " -> " << miss;
    }
    previous = miss;
    // energy 1/2 v.I v along the transported solution, and the library's checks. The order-2
    // scheme keeps it to O(h^2): measured relative drifts 4.4e-8 (SE(2)) and 1.8e-8 (SE(3)) at
    // N = 100, 8x less at N = 200 (O(h^3) here); 1e-3 h^2 leaves a factor 5 at N = 100.
    const double e0 = s.trajectory.v.front().dot(body.inertia() * s.trajectory.v.front());
    const double h = T / N;
    for (const auto& v : s.trajectory.v) EXPECT_NEAR(v.dot(body.inertia() * v), e0, 1e-3 * h * h * e0);
    EXPECT_TRUE(verify::verify_solution(problem, s, 1e-12).passed()) << verify::verify_solution(problem, s, 1e-12).text();
  }
}

TEST(FreeBody, SE2FollowsEulerPoincareAtLambdaZero) {
  expect_euler_poincare_at_lambda_zero<groups::SE2>(mechanics::SE2FreeBody(coupled_inertia<3>()),
                                                    groups::SE2::exp(Eigen::Vector3d(1.0, -0.5, 0.8)));
}

TEST(FreeBody, SE3FollowsEulerPoincareAtLambdaZero) {
  Eigen::Matrix<double, 6, 1> w;
  w << 0.6, -0.3, 0.5, 0.4, -0.7, 0.3;
  expect_euler_poincare_at_lambda_zero<groups::SE3>(mechanics::SE3FreeBody(coupled_inertia<6>()), groups::SE3::exp(w));
}

// The free bodies' Hamiltonians (1/2 mu.I^-1 mu) are the Legendre transforms of their Lagrangians:
// h(g, I v) = mu.v - l(g, v), dh/dmu = v, no group gradient (rounding of a few flops on O(1)
// values: 1e-13). Lie-Poisson from mu0 = I v0 then follows Euler-Poincare from v0: both RKMK4 with
// the same 2000 steps on equations related by the linear map I (Runge-Kutta commutes with it), so
// they agree to rounding accumulated over the steps (1e-9), and h is conserved to RKMK4's error
// (h^4 ~ 1e-12 at these step sizes; 1e-9 asserted).
template <groups::LieGroup G, class L, class H>
void expect_hamiltonian_is_the_legendre_transform(const L& body, const H& hamiltonian) {
  std::mt19937 rng(kSeed + 5);
  for (int trial = 0; trial < 5; ++trial) {
    const groups::ElementOf<G> g = G::exp(random_tangent<G>(rng, 1.0));
    const groups::TangentOf<G> v = random_tangent<G>(rng, 1.0);
    const groups::CovectorOf<G> mu = body.momentum(0, g, v);
    EXPECT_NEAR(hamiltonian.value(0, g, mu), mu.dot(v) - body.value(0, g, v), 1e-13);
    EXPECT_NEAR_MATRIX(hamiltonian.velocity(0, g, mu), v, 1e-13);
    EXPECT_EQ(hamiltonian.group_gradient(0, g, mu).norm(), 0.0);
  }
  const groups::TangentOf<G> v0 = random_tangent<G>(rng, 1.0);
  const auto ep = mechanics::euler_poincare<G>(groups::Side::Left, body, G::identity(), v0, 2.0, 2000);
  const auto lp = mechanics::lie_poisson<G>(groups::Side::Left, hamiltonian, G::identity(),
                                            body.momentum(0, G::identity(), v0), 2.0, 2000);
  ASSERT_EQ(lp.mu.size(), ep.mu.size());
  EXPECT_NEAR_MATRIX(lp.mu.back(), ep.mu.back(), 1e-9);
  EXPECT_NEAR_MATRIX(G::matrix(lp.g.back()), G::matrix(ep.g.back()), 1e-9);
  const double h0 = hamiltonian.value(0, lp.g.front(), lp.mu.front());
  for (std::size_t k = 0; k < lp.mu.size(); ++k) EXPECT_NEAR(hamiltonian.value(0, lp.g[k], lp.mu[k]), h0, 1e-9);
}

TEST(FreeBody, SE2HamiltonianIsTheLegendreTransform) {
  expect_hamiltonian_is_the_legendre_transform<groups::SE2>(mechanics::SE2FreeBody(coupled_inertia<3>()),
                                                            mechanics::SE2FreeBodyHamiltonian(coupled_inertia<3>()));
}

TEST(FreeBody, SE3HamiltonianIsTheLegendreTransform) {
  expect_hamiltonian_is_the_legendre_transform<groups::SE3>(mechanics::SE3FreeBody(coupled_inertia<6>()),
                                                            mechanics::SE3FreeBodyHamiltonian(coupled_inertia<6>()));
}

TEST(FreeBody, InertiaIsValidatedWithTheValueInTheMessage) {
  Eigen::Matrix3d asymmetric = coupled_inertia<3>();
  asymmetric(0, 1) += 1e-6;
  Eigen::Matrix3d indefinite = Eigen::Vector3d(1, -1, 1).asDiagonal();
  Eigen::Matrix3d non_finite = coupled_inertia<3>();
  non_finite(2, 2) = std::numeric_limits<double>::quiet_NaN();
  const auto message = [](const Eigen::Matrix3d& inertia) {
    try {
      mechanics::SE2FreeBody body(inertia);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(asymmetric).find("is not symmetric"), std::string::npos) << message(asymmetric);
  EXPECT_NE(message(indefinite).find("is not positive definite"), std::string::npos) << message(indefinite);
  EXPECT_NE(message(indefinite).find("inertia = [1, 0, 0; 0, -1, 0; 0, 0, 1]"), std::string::npos) << message(indefinite);
  EXPECT_NE(message(non_finite).find("inertia"), std::string::npos) << message(non_finite);
  EXPECT_THROW(mechanics::SE3FreeBody(-Eigen::Matrix<double, 6, 6>::Identity()), std::invalid_argument);
}

}  // namespace
}  // namespace cartan::testing
