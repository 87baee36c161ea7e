// The Lagrangian/Hamiltonian concepts, the models' derivatives against finite differences,
// their Legendre consistency, the generic Newton inverse Legendre map, and inertia validation.
#include <gtest/gtest.h>

#include "cartan/mechanics/euler_poincare.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "mechanics/mechanics_support.hpp"

namespace cartan::testing {
namespace {

static_assert(mechanics::ReducedLagrangian<mechanics::RigidBody, groups::SO3>);
static_assert(mechanics::ReducedLagrangian<mechanics::SpatialRigidBody, groups::SO3>);
static_assert(mechanics::ReducedLagrangian<mechanics::SO3Oscillator, groups::SO3>);
static_assert(mechanics::ReducedLagrangian<mechanics::H3Oscillator, groups::Heisenberg>);
static_assert(mechanics::ReducedHamiltonian<mechanics::RigidBodyHamiltonian, groups::SO3>);
static_assert(mechanics::ReducedHamiltonian<mechanics::SpatialRigidBodyHamiltonian, groups::SO3>);
static_assert(mechanics::ReducedHamiltonian<mechanics::H3OscillatorHamiltonian, groups::Heisenberg>);
static_assert(!mechanics::ReducedLagrangian<mechanics::RigidBodyHamiltonian, groups::SO3>);  // no momentum(t, g, v)
static_assert(!mechanics::ReducedHamiltonian<int, groups::SO3>);

// Central differences with step 1e-6 on O(1) smooth functions: truncation ~1e-12, rounding
// ~1e-16 / 1e-6 = 1e-10; 1e-8 leaves a margin of 100.
constexpr double kFdTolerance = 1e-8;

// Checks a Lagrangian's momentum and group gradient (left- or right-trivialised as `side`
// says) against finite differences of its value, and its inverse Legendre map.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void expect_lagrangian_derivatives(const L& l, groups::Side side, std::mt19937& rng) {
  for (int trial = 0; trial < 5; ++trial) {
    const groups::ElementOf<G> g = random_element<G>(rng, 1.5);
    const groups::TangentOf<G> v = random_tangent<G>(rng, 2.0);
    const double t = 0.3;
    const auto of_v = [&](const groups::TangentOf<G>& w) { return l.value(t, g, w); };
    const auto of_g = [&](const groups::ElementOf<G>& h) { return l.value(t, h, v); };
    EXPECT_NEAR_MATRIX(l.momentum(t, g, v), vector_gradient_fd(of_v, v), kFdTolerance);
    const groups::CovectorOf<G> zeta_fd =
        side == groups::Side::Left ? groups::left_gradient_fd<G>(of_g, g) : right_gradient_fd<G>(of_g, g);
    EXPECT_NEAR_MATRIX(l.group_gradient(t, g, v), zeta_fd, kFdTolerance) << to_string(side);
    EXPECT_NEAR_MATRIX(l.velocity(t, g, l.momentum(t, g, v)), v, 1e-12);
  }
}

// Checks a Hamiltonian's velocity and group gradient against finite differences, and its
// Legendre relation with a Lagrangian: v = dh/dmu, mu = dl/dv, h + l = mu . v, and
// zeta_h = -zeta_l (dh/dg at fixed mu is -dl/dg at fixed v).
template <groups::LieGroup G, mechanics::ReducedHamiltonian<G> H, mechanics::ReducedLagrangian<G> L>
void expect_hamiltonian_derivatives(const H& h, const L& l, groups::Side side, std::mt19937& rng) {
  for (int trial = 0; trial < 5; ++trial) {
    const groups::ElementOf<G> g = random_element<G>(rng, 1.5);
    const groups::CovectorOf<G> mu = random_tangent<G>(rng, 2.0);
    const double t = 0.3;
    const auto of_mu = [&](const groups::CovectorOf<G>& m) { return h.value(t, g, m); };
    const auto of_g = [&](const groups::ElementOf<G>& x) { return h.value(t, x, mu); };
    EXPECT_NEAR_MATRIX(h.velocity(t, g, mu), vector_gradient_fd(of_mu, mu), kFdTolerance);
    const groups::CovectorOf<G> zeta_fd =
        side == groups::Side::Left ? groups::left_gradient_fd<G>(of_g, g) : right_gradient_fd<G>(of_g, g);
    EXPECT_NEAR_MATRIX(h.group_gradient(t, g, mu), zeta_fd, kFdTolerance) << to_string(side);
    const groups::TangentOf<G> v = h.velocity(t, g, mu);
    EXPECT_NEAR_MATRIX(l.velocity(t, g, mu), v, 1e-12);
    EXPECT_NEAR(h.value(t, g, mu) + l.value(t, g, v), mu.dot(v), 1e-12);
    EXPECT_NEAR_MATRIX(h.group_gradient(t, g, mu), -l.group_gradient(t, g, v), 1e-12);
  }
}

TEST(Models, RigidBodyDerivatives) {
  std::mt19937 rng(kSeed);
  const mechanics::RigidBody body(kInertia);
  expect_lagrangian_derivatives<groups::SO3>(body, groups::Side::Left, rng);
  expect_lagrangian_derivatives<groups::SO3>(mechanics::SpatialRigidBody(body), groups::Side::Right, rng);
  expect_hamiltonian_derivatives<groups::SO3>(mechanics::RigidBodyHamiltonian(kInertia), body, groups::Side::Left, rng);
  expect_hamiltonian_derivatives<groups::SO3>(mechanics::SpatialRigidBodyHamiltonian(mechanics::RigidBodyHamiltonian(kInertia)),
                                      mechanics::SpatialRigidBody(body), groups::Side::Right, rng);
}

// l_+(g, v) = 1/2 (Ad_{g^-1} v) . I (Ad_{g^-1} v): momentum g I g^T v (the spatial angular
// momentum) and right-trivialised gradient ad*_v mu = -v x mu (mechanics/right_reduced.hpp).
TEST(Models, SpatialRigidBodyClosedForms) {
  std::mt19937 rng(kSeed + 1);
  const mechanics::SpatialRigidBody spatial{mechanics::RigidBody(kInertia)};
  for (int trial = 0; trial < 5; ++trial) {
    const groups::SO3::Element g = random_element<groups::SO3>(rng, 2.0);
    const groups::SO3::Tangent v = random_tangent<groups::SO3>(rng, 2.0);
    const groups::SO3::Tangent body_v = g.transpose() * v;
    EXPECT_NEAR(spatial.value(0, g, v), 0.5 * body_v.dot(kInertia * body_v), 1e-13);
    const groups::SO3::Tangent mu = g * kInertia * g.transpose() * v;
    EXPECT_NEAR_MATRIX(spatial.momentum(0, g, v), mu, 1e-13);
    EXPECT_NEAR_MATRIX(spatial.group_gradient(0, g, v), -v.cross(mu), 1e-13);
    EXPECT_NEAR_MATRIX(spatial.group_gradient(0, g, v), groups::coad<groups::SO3>(v, mu), 1e-13);
  }
}

TEST(Models, SO3OscillatorDerivatives) {
  std::mt19937 rng(kSeed + 2);
  const mechanics::SO3Oscillator oscillator(kInertia);
  const mechanics::SO3OscillatorHamiltonian hamiltonian(kInertia);
  expect_lagrangian_derivatives<groups::SO3>(oscillator, groups::Side::Left, rng);
  expect_lagrangian_derivatives<groups::SO3>(mechanics::right_reduced_lagrangian<groups::SO3>(oscillator), groups::Side::Right, rng);
  expect_hamiltonian_derivatives<groups::SO3>(hamiltonian, oscillator, groups::Side::Left, rng);
  expect_hamiltonian_derivatives<groups::SO3>(mechanics::right_reduced_hamiltonian<groups::SO3>(hamiltonian),
                                      mechanics::right_reduced_lagrangian<groups::SO3>(oscillator), groups::Side::Right, rng);
}

// docs/paper-notes.md#erratum-1: zeta = -vee(Skew g) (the paper prints +vee(Skew g)). Besides the
// finite-difference check above: the force restores, mu' = zeta ~ -theta x at g = exp(theta x).
TEST(Models, SO3OscillatorForceRestores) {
  const mechanics::SO3Oscillator oscillator(kInertia);
  std::mt19937 rng(kSeed + 3);
  for (int trial = 0; trial < 5; ++trial) {
    const groups::SO3::Element g = random_element<groups::SO3>(rng, 2.0);
    EXPECT_NEAR_MATRIX(oscillator.group_gradient(0, g, groups::SO3::Tangent::Zero()),
                       -0.5 * groups::SO3::vee(groups::SO3::Element(g - g.transpose())), 1e-15);
  }
  const groups::SO3::Tangent x(1e-3, -2e-3, 0.5e-3);
  EXPECT_NEAR_MATRIX(oscillator.group_gradient(0, groups::SO3::exp(x), groups::SO3::Tangent::Zero()), -x, 1e-8);  // O(theta^3)
}

TEST(Models, H3OscillatorDerivatives) {
  std::mt19937 rng(kSeed + 4);
  const mechanics::H3Oscillator oscillator = mechanics::h3_oscillator();
  const mechanics::H3OscillatorHamiltonian hamiltonian = mechanics::h3_oscillator_hamiltonian();
  expect_lagrangian_derivatives<groups::Heisenberg>(oscillator, groups::Side::Left, rng);
  expect_lagrangian_derivatives<groups::Heisenberg>(mechanics::right_reduced_lagrangian<groups::Heisenberg>(oscillator), groups::Side::Right, rng);
  expect_hamiltonian_derivatives<groups::Heisenberg>(hamiltonian, oscillator, groups::Side::Left, rng);
  expect_hamiltonian_derivatives<groups::Heisenberg>(mechanics::right_reduced_hamiltonian<groups::Heisenberg>(hamiltonian),
                                             mechanics::right_reduced_lagrangian<groups::Heisenberg>(oscillator), groups::Side::Right, rng);
  // The closed form dV = (a, b + a c, c) is the left-trivialisation (group.hpp) of the ambient
  // gradient (a, b, c) of V.
  for (int trial = 0; trial < 5; ++trial) {
    const groups::Heisenberg::Element g = random_element<groups::Heisenberg>(rng, 2.0);
    EXPECT_NEAR_MATRIX(oscillator.potential().left_gradient(g), groups::left_trivialise_covector<groups::Heisenberg>(g, g), 1e-14);
  }
}

// ---- The Newton inverse Legendre map, on a user-defined model. --------------------------

// A user type satisfying ReducedLagrangian without an analytic inverse Legendre map:
// l = 1/2 v . I v + 1/4 |v|^4 (strictly convex), mu = I v + |v|^2 v.
struct QuarticRigidBody {
  Eigen::Matrix3d inertia = kInertia;
  double value(double, const groups::SO3::Element&, const groups::SO3::Tangent& v) const {
    return 0.5 * v.dot(inertia * v) + 0.25 * v.squaredNorm() * v.squaredNorm();
  }
  groups::SO3::Tangent momentum(double, const groups::SO3::Element&, const groups::SO3::Tangent& v) const {
    return inertia * v + v.squaredNorm() * v;
  }
  groups::SO3::Tangent group_gradient(double, const groups::SO3::Element&, const groups::SO3::Tangent&) const { return groups::SO3::Tangent::Zero(); }
  Eigen::Matrix3d hessian(const groups::SO3::Tangent& v) const {
    return inertia + v.squaredNorm() * Eigen::Matrix3d::Identity() + 2 * v * v.transpose();
  }
  groups::SO3::Tangent velocity(double t, const groups::SO3::Element& g, const groups::SO3::Tangent& mu) const {
    const auto p = [&](const groups::SO3::Tangent& v) { return momentum(t, g, v); };
    return mechanics::inverse_legendre<groups::SO3>(p, mu, groups::SO3::Tangent(inertia.ldlt().solve(mu)));
  }
};
static_assert(mechanics::ReducedLagrangian<QuarticRigidBody, groups::SO3>);

TEST(InverseLegendre, SolvesWithFiniteDifferenceAndAnalyticJacobians) {
  const QuarticRigidBody model;
  std::mt19937 rng(kSeed + 5);
  for (int trial = 0; trial < 10; ++trial) {
    const groups::SO3::Tangent v = random_tangent<groups::SO3>(rng, 3.0);
    const groups::SO3::Tangent mu = model.momentum(0, groups::SO3::identity(), v);
    // The solution is unique (l strictly convex); the Newton tolerance 1e-13 (1 + |mu|) on the
    // residual and a Jacobian with eigenvalues >= 1.7 bound the error by ~1e-12 (1 + |mu|).
    EXPECT_NEAR_MATRIX(model.velocity(0, groups::SO3::identity(), mu), v, 1e-11 * (1 + mu.norm()));
    const auto p = [&](const groups::SO3::Tangent& w) { return model.momentum(0, groups::SO3::identity(), w); };
    const auto jac = [&](const groups::SO3::Tangent& w) { return model.hessian(w); };
    EXPECT_NEAR_MATRIX(mechanics::inverse_legendre<groups::SO3>(p, jac, mu, groups::SO3::Tangent::Zero()), v, 1e-11 * (1 + mu.norm()));
  }
}

// The energy mu . v - l of the quartic body is conserved by eq:EP-left at order 4: the Newton
// inverse drives a whole integration.
TEST(InverseLegendre, DrivesAnEulerPoincareIntegration) {
  const QuarticRigidBody model;
  const groups::SO3::Element g0 = groups::SO3::exp(groups::SO3::Tangent(0.1, 0.2, -0.3));
  const groups::SO3::Tangent v0(0.6, -0.4, 0.5);
  std::vector<double> drifts;
  for (int steps : {40, 80, 160}) {
    const auto trajectory = mechanics::euler_poincare<groups::SO3>(groups::Side::Left, model, g0, v0, 5.0, steps);
    drifts.push_back(max_drift(trajectory, [&](std::size_t k) {
      return mechanics::lagrangian_energy<groups::SO3>(model, trajectory.t[k], trajectory.g[k], trajectory.v[k]);
    }));
  }
  for (double order : measured_orders("quartic body energy drift (Newton inverse Legendre)", drifts)) {
    EXPECT_GT(order, 3.5);
    EXPECT_LT(order, 4.6);
  }
}

// momentum(v) = v / sqrt(1 + |v|^2) never reaches |mu| >= 1: Newton must fail and say so.
TEST(InverseLegendre, ReportsNonConvergence) {
  const auto bounded = [](const groups::SO3::Tangent& v) { return groups::SO3::Tangent(v / std::sqrt(1 + v.squaredNorm())); };
  const groups::SO3::Tangent mu(2.0, 0.0, 0.0);
  try {
    mechanics::inverse_legendre<groups::SO3>(bounded, mu, groups::SO3::Tangent::Zero());
    FAIL() << "expected InverseLegendreError";
  } catch (const mechanics::InverseLegendreError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("iterations"), std::string::npos) << message;
    EXPECT_NE(message.find("residual"), std::string::npos) << message;
    EXPECT_NE(message.find("mu = [2"), std::string::npos) << message;
    EXPECT_GT(e.residual(), 0.5);  // |mu| - sup|momentum| = 1
    EXPECT_GT(e.iterations(), 0);
  }
  // A singular Jacobian (momentum ignores v3) with mu3 != 0.
  const auto degenerate = [](const groups::SO3::Tangent& v) { return groups::SO3::Tangent(v[0], v[1], 0.0); };
  EXPECT_THROW(mechanics::inverse_legendre<groups::SO3>(degenerate, groups::SO3::Tangent(1, 1, 1), groups::SO3::Tangent::Zero()), mechanics::InverseLegendreError);
  // No iterations allowed from a wrong guess.
  mechanics::InverseLegendreOptions no_iterations;
  no_iterations.max_iterations = 0;
  const auto identity_map = [](const groups::SO3::Tangent& v) { return v; };
  EXPECT_THROW(mechanics::inverse_legendre<groups::SO3>(identity_map, groups::SO3::Tangent(1, 0, 0), groups::SO3::Tangent::Zero(), no_iterations),
               mechanics::InverseLegendreError);
  EXPECT_THROW(mechanics::inverse_legendre<groups::SO3>(identity_map, groups::SO3::Tangent(NAN, 0, 0), groups::SO3::Tangent::Zero()),
               std::invalid_argument);
}

// ---- Inertia validation. ------------------------------------------------------------------

void expect_inertia_rejected(const Eigen::Matrix3d& inertia, const std::string& problem) {
  for (int model = 0; model < 2; ++model) {
    try {
      if (model == 0) {
        mechanics::RigidBody body(inertia);
      } else {
        mechanics::SO3OscillatorHamiltonian hamiltonian(inertia);
      }
      FAIL() << "accepted inertia " << format_value(inertia);
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("inertia = ["), std::string::npos) << message;
      EXPECT_NE(message.find(problem), std::string::npos) << message;
    }
  }
}

TEST(Models, RejectsInvalidInertia) {
  expect_inertia_rejected(Eigen::Vector3d(1, -2, 3).asDiagonal(), "not positive definite");
  expect_inertia_rejected(Eigen::Vector3d(1, 0, 3).asDiagonal(), "not positive definite");
  Eigen::Matrix3d asymmetric = kInertia;
  asymmetric(0, 1) += 0.5;
  expect_inertia_rejected(asymmetric, "not symmetric");
  Eigen::Matrix3d nan = kInertia;
  nan(2, 2) = NAN;
  expect_inertia_rejected(nan, "non-finite");
  Eigen::Matrix3d inf = kInertia;
  inf(1, 0) = inf(0, 1) = INFINITY;
  expect_inertia_rejected(inf, "non-finite");
  EXPECT_NO_THROW(mechanics::RigidBody{kInertia});
}

}  // namespace
}  // namespace cartan::testing
