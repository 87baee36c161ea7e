// The Lagrangian/Hamiltonian concepts, the models' derivatives against finite differences,
// their Legendre consistency, the generic Newton inverse Legendre map, and inertia validation.
#include <gtest/gtest.h>

#include "cartan/euler_poincare.hpp"
#include "cartan/lagrangian.hpp"
#include "cartan/models/heisenberg_oscillator.hpp"
#include "cartan/models/rigid_body.hpp"
#include "mechanics/mechanics_support.hpp"

namespace cartan::testing {
namespace {

const Eigen::Matrix3d kInertia = (Eigen::Matrix3d() << 2.0, 0.3, 0.1, 0.3, 3.0, -0.2, 0.1, -0.2, 4.0).finished();

static_assert(ReducedLagrangian<RigidBody, SO3>);
static_assert(ReducedLagrangian<SpatialRigidBody, SO3>);
static_assert(ReducedLagrangian<SO3Oscillator, SO3>);
static_assert(ReducedLagrangian<H3Oscillator, Heisenberg>);
static_assert(ReducedHamiltonian<RigidBodyHamiltonian, SO3>);
static_assert(ReducedHamiltonian<SpatialRigidBodyHamiltonian, SO3>);
static_assert(ReducedHamiltonian<H3OscillatorHamiltonian, Heisenberg>);
static_assert(!ReducedLagrangian<RigidBodyHamiltonian, SO3>);  // no momentum(t, g, v)
static_assert(!ReducedHamiltonian<int, SO3>);

// Central differences with step 1e-6 on O(1) smooth functions: truncation ~1e-12, rounding
// ~1e-16 / 1e-6 = 1e-10; 1e-8 leaves a margin of 100.
constexpr double kFdTolerance = 1e-8;

// Checks a Lagrangian's momentum and group gradient (left- or right-trivialised as `side`
// says) against finite differences of its value, and its inverse Legendre map.
template <LieGroup G, ReducedLagrangian<G> L>
void expect_lagrangian_derivatives(const L& l, Side side, std::mt19937& rng) {
  for (int trial = 0; trial < 5; ++trial) {
    const ElementOf<G> g = random_element<G>(rng, 1.5);
    const TangentOf<G> v = random_tangent<G>(rng, 2.0);
    const double t = 0.3;
    const auto of_v = [&](const TangentOf<G>& w) { return l.value(t, g, w); };
    const auto of_g = [&](const ElementOf<G>& h) { return l.value(t, h, v); };
    EXPECT_NEAR_MATRIX(l.momentum(t, g, v), vector_gradient_fd(of_v, v), kFdTolerance);
    const CovectorOf<G> zeta_fd =
        side == Side::Left ? left_gradient_fd<G>(of_g, g) : right_gradient_fd<G>(of_g, g);
    EXPECT_NEAR_MATRIX(l.group_gradient(t, g, v), zeta_fd, kFdTolerance) << to_string(side);
    EXPECT_NEAR_MATRIX(l.velocity(t, g, l.momentum(t, g, v)), v, 1e-12);
  }
}

// Checks a Hamiltonian's velocity and group gradient against finite differences, and its
// Legendre relation with a Lagrangian: v = dh/dmu, mu = dl/dv, h + l = mu . v, and
// zeta_h = -zeta_l (dh/dg at fixed mu is -dl/dg at fixed v).
template <LieGroup G, ReducedHamiltonian<G> H, ReducedLagrangian<G> L>
void expect_hamiltonian_derivatives(const H& h, const L& l, Side side, std::mt19937& rng) {
  for (int trial = 0; trial < 5; ++trial) {
    const ElementOf<G> g = random_element<G>(rng, 1.5);
    const CovectorOf<G> mu = random_tangent<G>(rng, 2.0);
    const double t = 0.3;
    const auto of_mu = [&](const CovectorOf<G>& m) { return h.value(t, g, m); };
    const auto of_g = [&](const ElementOf<G>& x) { return h.value(t, x, mu); };
    EXPECT_NEAR_MATRIX(h.velocity(t, g, mu), vector_gradient_fd(of_mu, mu), kFdTolerance);
    const CovectorOf<G> zeta_fd =
        side == Side::Left ? left_gradient_fd<G>(of_g, g) : right_gradient_fd<G>(of_g, g);
    EXPECT_NEAR_MATRIX(h.group_gradient(t, g, mu), zeta_fd, kFdTolerance) << to_string(side);
    const TangentOf<G> v = h.velocity(t, g, mu);
    EXPECT_NEAR_MATRIX(l.velocity(t, g, mu), v, 1e-12);
    EXPECT_NEAR(h.value(t, g, mu) + l.value(t, g, v), mu.dot(v), 1e-12);
    EXPECT_NEAR_MATRIX(h.group_gradient(t, g, mu), -l.group_gradient(t, g, v), 1e-12);
  }
}

TEST(Models, RigidBodyDerivatives) {
  std::mt19937 rng(kSeed);
  const RigidBody body(kInertia);
  expect_lagrangian_derivatives<SO3>(body, Side::Left, rng);
  expect_lagrangian_derivatives<SO3>(SpatialRigidBody(body), Side::Right, rng);
  expect_hamiltonian_derivatives<SO3>(RigidBodyHamiltonian(kInertia), body, Side::Left, rng);
  expect_hamiltonian_derivatives<SO3>(SpatialRigidBodyHamiltonian(RigidBodyHamiltonian(kInertia)),
                                      SpatialRigidBody(body), Side::Right, rng);
}

// l_+(g, v) = 1/2 (Ad_{g^-1} v) . I (Ad_{g^-1} v): momentum g I g^T v (the spatial angular
// momentum) and right-trivialised gradient ad*_v mu = -v x mu (models/right_reduced.hpp).
TEST(Models, SpatialRigidBodyClosedForms) {
  std::mt19937 rng(kSeed + 1);
  const SpatialRigidBody spatial{RigidBody(kInertia)};
  for (int trial = 0; trial < 5; ++trial) {
    const SO3::Element g = random_element<SO3>(rng, 2.0);
    const SO3::Tangent v = random_tangent<SO3>(rng, 2.0);
    const SO3::Tangent body_v = g.transpose() * v;
    EXPECT_NEAR(spatial.value(0, g, v), 0.5 * body_v.dot(kInertia * body_v), 1e-13);
    const SO3::Tangent mu = g * kInertia * g.transpose() * v;
    EXPECT_NEAR_MATRIX(spatial.momentum(0, g, v), mu, 1e-13);
    EXPECT_NEAR_MATRIX(spatial.group_gradient(0, g, v), -v.cross(mu), 1e-13);
    EXPECT_NEAR_MATRIX(spatial.group_gradient(0, g, v), coad<SO3>(v, mu), 1e-13);
  }
}

TEST(Models, SO3OscillatorDerivatives) {
  std::mt19937 rng(kSeed + 2);
  const SO3Oscillator oscillator(kInertia);
  const SO3OscillatorHamiltonian hamiltonian(kInertia);
  expect_lagrangian_derivatives<SO3>(oscillator, Side::Left, rng);
  expect_lagrangian_derivatives<SO3>(right_reduced_lagrangian<SO3>(oscillator), Side::Right, rng);
  expect_hamiltonian_derivatives<SO3>(hamiltonian, oscillator, Side::Left, rng);
  expect_hamiltonian_derivatives<SO3>(right_reduced_hamiltonian<SO3>(hamiltonian),
                                      right_reduced_lagrangian<SO3>(oscillator), Side::Right, rng);
}

// docs/paper-notes.md#erratum-1: zeta = -vee(Skew g) (the paper prints +vee(Skew g)). Besides the
// finite-difference check above: the force restores, mu' = zeta ~ -theta x at g = exp(theta x).
TEST(Models, SO3OscillatorForceRestores) {
  const SO3Oscillator oscillator(kInertia);
  std::mt19937 rng(kSeed + 3);
  for (int trial = 0; trial < 5; ++trial) {
    const SO3::Element g = random_element<SO3>(rng, 2.0);
    EXPECT_NEAR_MATRIX(oscillator.group_gradient(0, g, SO3::Tangent::Zero()),
                       -0.5 * SO3::vee(SO3::Element(g - g.transpose())), 1e-15);
  }
  const SO3::Tangent x(1e-3, -2e-3, 0.5e-3);
  EXPECT_NEAR_MATRIX(oscillator.group_gradient(0, SO3::exp(x), SO3::Tangent::Zero()), -x, 1e-8);  // O(theta^3)
}

TEST(Models, H3OscillatorDerivatives) {
  std::mt19937 rng(kSeed + 4);
  const H3Oscillator oscillator = h3_oscillator();
  const H3OscillatorHamiltonian hamiltonian = h3_oscillator_hamiltonian();
  expect_lagrangian_derivatives<Heisenberg>(oscillator, Side::Left, rng);
  expect_lagrangian_derivatives<Heisenberg>(right_reduced_lagrangian<Heisenberg>(oscillator), Side::Right, rng);
  expect_hamiltonian_derivatives<Heisenberg>(hamiltonian, oscillator, Side::Left, rng);
  expect_hamiltonian_derivatives<Heisenberg>(right_reduced_hamiltonian<Heisenberg>(hamiltonian),
                                             right_reduced_lagrangian<Heisenberg>(oscillator), Side::Right, rng);
  // The closed form dV = (a, b + a c, c) is the left-trivialisation (group.hpp) of the ambient
  // gradient (a, b, c) of V.
  for (int trial = 0; trial < 5; ++trial) {
    const Heisenberg::Element g = random_element<Heisenberg>(rng, 2.0);
    EXPECT_NEAR_MATRIX(oscillator.potential().left_gradient(g), left_trivialise_covector<Heisenberg>(g, g), 1e-14);
  }
}

// ---- The Newton inverse Legendre map, on a user-defined model. --------------------------

// A user type satisfying ReducedLagrangian without an analytic inverse Legendre map:
// l = 1/2 v . I v + 1/4 |v|^4 (strictly convex), mu = I v + |v|^2 v.
struct QuarticRigidBody {
  Eigen::Matrix3d inertia = kInertia;
  double value(double, const SO3::Element&, const SO3::Tangent& v) const {
    return 0.5 * v.dot(inertia * v) + 0.25 * v.squaredNorm() * v.squaredNorm();
  }
  SO3::Tangent momentum(double, const SO3::Element&, const SO3::Tangent& v) const {
    return inertia * v + v.squaredNorm() * v;
  }
  SO3::Tangent group_gradient(double, const SO3::Element&, const SO3::Tangent&) const { return SO3::Tangent::Zero(); }
  Eigen::Matrix3d hessian(const SO3::Tangent& v) const {
    return inertia + v.squaredNorm() * Eigen::Matrix3d::Identity() + 2 * v * v.transpose();
  }
  SO3::Tangent velocity(double t, const SO3::Element& g, const SO3::Tangent& mu) const {
    const auto p = [&](const SO3::Tangent& v) { return momentum(t, g, v); };
    return inverse_legendre<SO3>(p, mu, SO3::Tangent(inertia.ldlt().solve(mu)));
  }
};
static_assert(ReducedLagrangian<QuarticRigidBody, SO3>);

TEST(InverseLegendre, SolvesWithFiniteDifferenceAndAnalyticJacobians) {
  const QuarticRigidBody model;
  std::mt19937 rng(kSeed + 5);
  for (int trial = 0; trial < 10; ++trial) {
    const SO3::Tangent v = random_tangent<SO3>(rng, 3.0);
    const SO3::Tangent mu = model.momentum(0, SO3::identity(), v);
    // The solution is unique (l strictly convex); the Newton tolerance 1e-13 (1 + |mu|) on the
    // residual and a Jacobian with eigenvalues >= 1.7 bound the error by ~1e-12 (1 + |mu|).
    EXPECT_NEAR_MATRIX(model.velocity(0, SO3::identity(), mu), v, 1e-11 * (1 + mu.norm()));
    const auto p = [&](const SO3::Tangent& w) { return model.momentum(0, SO3::identity(), w); };
    const auto jac = [&](const SO3::Tangent& w) { return model.hessian(w); };
    EXPECT_NEAR_MATRIX(inverse_legendre<SO3>(p, jac, mu, SO3::Tangent::Zero()), v, 1e-11 * (1 + mu.norm()));
  }
}

// The energy mu . v - l of the quartic body is conserved by eq:EP-left at order 4: the Newton
// inverse drives a whole integration.
TEST(InverseLegendre, DrivesAnEulerPoincareIntegration) {
  const QuarticRigidBody model;
  const SO3::Element g0 = SO3::exp(SO3::Tangent(0.1, 0.2, -0.3));
  const SO3::Tangent v0(0.6, -0.4, 0.5);
  std::vector<double> drifts;
  for (int steps : {40, 80, 160}) {
    const auto trajectory = euler_poincare<SO3>(Side::Left, model, g0, v0, 5.0, steps);
    drifts.push_back(max_drift(trajectory, [&](std::size_t k) {
      return lagrangian_energy<SO3>(model, trajectory.t[k], trajectory.g[k], trajectory.v[k]);
    }));
  }
  for (double order : measured_orders("quartic body energy drift (Newton inverse Legendre)", drifts)) {
    EXPECT_GT(order, 3.5);
    EXPECT_LT(order, 4.6);
  }
}

// momentum(v) = v / sqrt(1 + |v|^2) never reaches |mu| >= 1: Newton must fail and say so.
TEST(InverseLegendre, ReportsNonConvergence) {
  const auto bounded = [](const SO3::Tangent& v) { return SO3::Tangent(v / std::sqrt(1 + v.squaredNorm())); };
  const SO3::Tangent mu(2.0, 0.0, 0.0);
  try {
    inverse_legendre<SO3>(bounded, mu, SO3::Tangent::Zero());
    FAIL() << "expected InverseLegendreError";
  } catch (const InverseLegendreError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("iterations"), std::string::npos) << message;
    EXPECT_NE(message.find("residual"), std::string::npos) << message;
    EXPECT_NE(message.find("mu = [2"), std::string::npos) << message;
    EXPECT_GT(e.residual(), 0.5);  // |mu| - sup|momentum| = 1
    EXPECT_GT(e.iterations(), 0);
  }
  // A singular Jacobian (momentum ignores v3) with mu3 != 0.
  const auto degenerate = [](const SO3::Tangent& v) { return SO3::Tangent(v[0], v[1], 0.0); };
  EXPECT_THROW(inverse_legendre<SO3>(degenerate, SO3::Tangent(1, 1, 1), SO3::Tangent::Zero()), InverseLegendreError);
  // No iterations allowed from a wrong guess.
  InverseLegendreOptions no_iterations;
  no_iterations.max_iterations = 0;
  const auto identity_map = [](const SO3::Tangent& v) { return v; };
  EXPECT_THROW(inverse_legendre<SO3>(identity_map, SO3::Tangent(1, 0, 0), SO3::Tangent::Zero(), no_iterations),
               InverseLegendreError);
  EXPECT_THROW(inverse_legendre<SO3>(identity_map, SO3::Tangent(NAN, 0, 0), SO3::Tangent::Zero()),
               std::invalid_argument);
}

// ---- Inertia validation. ------------------------------------------------------------------

void expect_inertia_rejected(const Eigen::Matrix3d& inertia, const std::string& problem) {
  for (int model = 0; model < 2; ++model) {
    try {
      if (model == 0) {
        RigidBody body(inertia);
      } else {
        SO3OscillatorHamiltonian hamiltonian(inertia);
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
  EXPECT_NO_THROW(RigidBody{kInertia});
}

}  // namespace
}  // namespace cartan::testing
