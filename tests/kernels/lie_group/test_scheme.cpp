// The discrete transported-velocity scheme: its tangent-linear map, and the agreement of the
// augmented shooting with the paper's two-level fixed point.
#include <limits>
#include <string>

#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"  // erased(problem)
#include "cartan/methods/lie_group/continuation.hpp"
#include "cartan/methods/lie_group/two_level.hpp"
#include "test_support.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace cartan::testing {
namespace {

// The shooting map x = (v0, xi0) -> (log(gT^{-1} g_N), xi_N) and its Jacobian from one
// tangent-linear sweep, compared with central differences (step 1e-6: truncation ~1e-12
// |r'''|, rounding ~1e-16 N / 1e-6 ~ 1e-8 for N = 40): relative agreement 1e-6.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void expect_tangent_matches_differences(const transported::TransportedProblem<G, L>& problem, transported::SchemeOrder order,
                                        std::mt19937& rng) {
  constexpr int n = G::kDim;
  const transported::TransportedScheme<G, L> scheme(problem, order);
  auto shoot = [&](const Eigen::VectorXd& x, int columns, transported::SweepOutput<G, L>& out) {
    EXPECT_TRUE(transported::forward_sweep(scheme, groups::TangentOf<G>(x.head<n>()), groups::CovectorOf<G>(x.tail<n>()), nullptr, columns, out))
        << out.failure;
    Eigen::VectorXd r(2 * n);
    r << scheme.terminal_residual(out.last), out.last.xi;
    return r;
  };
  const Eigen::VectorXd x = random_vector<Eigen::Matrix<double, 2 * n, 1>>(rng, 0.5);
  transported::SweepOutput<G, L> out;
  const Eigen::VectorXd r = shoot(x, 2 * n, out);
  Eigen::MatrixXd jac(2 * n, 2 * n);
  jac.topRows(n) = scheme.terminal_residual_tangent(r.head<n>(), *out.tangent);
  jac.bottomRows(n) = out.tangent->xi;
  const double step = 1e-6;
  for (int i = 0; i < 2 * n; ++i) {
    Eigen::VectorXd xp = x, xm = x;
    xp[i] += step;
    xm[i] -= step;
    transported::SweepOutput<G, L> op, om;
    const Eigen::VectorXd column = (shoot(xp, 0, op) - shoot(xm, 0, om)) / (2 * step);
    EXPECT_LE((jac.col(i) - column).norm(), 1e-6 * (1 + column.norm()))
        << G::name() << " lambda " << problem.lambda << " order " << static_cast<int>(order) << " column " << i
        << "\nanalytic " << jac.col(i).transpose() << "\nfd       " << column.transpose();
  }
}

/// A model with its declared Hessian structure hidden (mechanics/lagrangian_hessian.hpp), so that
/// the general path of the tangent-linear step - every block, d^2 l/dv^2 factorised at each node -
/// is checked on the same problems as the structured one.
template <class L>
struct WithoutStructure : L {
  explicit WithoutStructure(const L& l) : L(l) {}
  static constexpr bool kConstantMomentumHessian = false;
  static constexpr bool kGroupGradientIndependentOfVelocity = false;
  static constexpr bool kZeroGroupGradient = false;
};
template <groups::LieGroup G, class L>
transported::TransportedProblem<G, WithoutStructure<L>> without_structure(const transported::TransportedProblem<G, L>& p) {
  static_assert(mechanics::HessianStructure<L>::constant_momentum_hessian);
  static_assert(!mechanics::HessianStructure<WithoutStructure<L>>::constant_momentum_hessian);
  return {WithoutStructure<L>(p.lagrangian), p.lambda, p.T, p.N, p.g0, p.gT};
}

TEST(TransportedScheme, TangentLinearMatchesFiniteDifferences) {
  std::mt19937 rng(kSeed);
  for (double lambda : {0.0, 0.5, 1.0, 1.4, -0.2}) {
    for (transported::SchemeOrder order : {transported::SchemeOrder::First, transported::SchemeOrder::Second}) {
      auto oscillator = paper_oscillator(lambda, 40, 2.0);
      expect_tangent_matches_differences(oscillator, order, rng);
      auto free_body = paper_free_body(lambda, 40, 3.0);
      expect_tangent_matches_differences(free_body, order, rng);
      const transported::TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator> h3{mechanics::h3_oscillator(), lambda, 1.0, 40,
                                                                    groups::Heisenberg::Element(0.2, -0.1, 0.3),
                                                                    groups::Heisenberg::Element(1.0, 0.5, 0.8)};
      expect_tangent_matches_differences(h3, order, rng);
      expect_tangent_matches_differences(without_structure(oscillator), order, rng);
      expect_tangent_matches_differences(without_structure(free_body), order, rng);
      // Behind the erased type: the structure read at run time (constant mu_v, the Hessian held).
      expect_tangent_matches_differences(transported::erased(oscillator), order, rng);
      expect_tangent_matches_differences(transported::erased(free_body), order, rng);
      // The closed-form left Jacobians of SE(2) and SE(3) inside the step.
      const transported::TransportedProblem<groups::SE2, mechanics::SE2FreeBody> se2{
          mechanics::SE2FreeBody(Eigen::Vector3d(2, 1, 3).asDiagonal()), lambda, 2.0, 40, groups::SE2::identity(),
          groups::SE2::exp(Eigen::Vector3d(0.7, 1.0, -0.4))};
      expect_tangent_matches_differences(se2, order, rng);
      using V6 = Eigen::Matrix<double, 6, 1>;
      const transported::TransportedProblem<groups::SE3, mechanics::SE3FreeBody> se3{
          mechanics::SE3FreeBody(V6(1, 2, 3, 4, 4, 4).asDiagonal()), lambda, 2.0, 40, groups::SE3::identity(),
          groups::SE3::exp((V6() << 0.3, -0.2, 0.5, 1.0, 0.4, -0.6).finished())};
      expect_tangent_matches_differences(se3, order, rng);
    }
  }
}

// The models' analytic second derivatives against central differences of their first
// derivatives (step 1e-5: error ~1e-10 on O(1) entries). The static_assert makes sure the
// analytic path is the one under test (lagrangian_hessian falls back to differences otherwise).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void expect_hessian_matches_differences(const L& l, std::mt19937& rng) {
  static_assert(requires(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
    { l.hessian(t, g, v) } -> std::convertible_to<mechanics::LagrangianHessian<G>>;
  }, "the model must provide an analytic hessian(t, g, v)");
  for (int trial = 0; trial < 5; ++trial) {
    const auto g = random_element<G>(rng, 1.5);
    const auto v = random_tangent<G>(rng, 2.0);
    const auto analytic = mechanics::lagrangian_hessian<G>(l, 0.3, g, v);
    const auto fd = mechanics::lagrangian_hessian_fd<G>(l, 0.3, g, v);
    EXPECT_NEAR_MATRIX(analytic.momentum_v, fd.momentum_v, 1e-8);
    EXPECT_NEAR_MATRIX(analytic.momentum_g, fd.momentum_g, 1e-8);
    EXPECT_NEAR_MATRIX(analytic.gradient_v, fd.gradient_v, 1e-8);
    EXPECT_NEAR_MATRIX(analytic.gradient_g, fd.gradient_g, 1e-8);
  }
}

TEST(TransportedScheme, ModelHessiansMatchFiniteDifferences) {
  std::mt19937 rng(kSeed);
  expect_hessian_matches_differences<groups::SO3>(mechanics::RigidBody(paper_inertia()), rng);
  expect_hessian_matches_differences<groups::SO3>(mechanics::SO3Oscillator(paper_inertia()), rng);
  expect_hessian_matches_differences<groups::Heisenberg>(mechanics::h3_oscillator(), rng);
}

// docs/paper-notes.md#erratum-4: the augmented shooting reaches the same discrete solution as the
// two-level fixed point, for both schemes (the order-2 predictor is the same in both modes).
// With the outer tolerance at 1e-13 the two differ by the remaining fixed-point error only;
// 1e-10 on v0 and on every g_k and xi_k is the figure docs/paper-notes.md#erratum-4 records.
template <class Problem>
void expect_augmented_equals_two_level(const Problem& problem, transported::SchemeOrder order, const std::string& what) {
  const auto shooting = transported::solve_shooting(problem, {.order = order, .tolerance = 1e-12});
  const auto two_level = transported::solve_two_level(problem, {.order = order, .tolerance = 1e-13});
  ASSERT_TRUE(shooting.converged()) << what << shooting.message;
  ASSERT_TRUE(two_level.converged()) << what << two_level.message;
  EXPECT_LE((shooting.v0 - two_level.v0).norm(), 1e-10) << what;
  double worst = 0;
  for (std::size_t k = 0; k < shooting.trajectory.g.size(); ++k) {
    worst = std::max(worst, max_abs_diff(shooting.trajectory.g[k], two_level.trajectory.g[k]));
    worst = std::max(worst, max_abs_diff(shooting.trajectory.xi[k], two_level.trajectory.xi[k]));
  }
  EXPECT_LE(worst, 1e-10) << what;
}

TEST(TransportedScheme, AugmentedShootingEqualsTwoLevelFixedPoint) {
  for (transported::SchemeOrder order : {transported::SchemeOrder::First, transported::SchemeOrder::Second}) {
    for (double lambda : {0.0, 0.5, 1.0}) {
      const std::string what = "order " + std::to_string(static_cast<int>(order)) + " lambda " + std::to_string(lambda);
      expect_augmented_equals_two_level(paper_free_body(lambda), order, "free body " + what + ": ");
      expect_augmented_equals_two_level(paper_oscillator(lambda, 200, 3.0), order, "oscillator T = 3 " + what + ": ");
    }
  }
}

// Analytic and finite-difference Jacobians lead to the same solution; the analytic one needs
// far fewer sweeps (each tangent sweep counts once; a finite-difference Jacobian costs 2n + 1).
TEST(TransportedScheme, AnalyticJacobianSavesSweeps) {
  const auto problem = paper_free_body(0.5);
  const auto analytic = transported::solve_shooting(problem, {.tolerance = 1e-11});
  const auto differences = transported::solve_shooting(problem, {.tolerance = 1e-11, .analytic_jacobian = false});
  ASSERT_TRUE(analytic.converged()) << analytic.message;
  ASSERT_TRUE(differences.converged()) << differences.message;
  EXPECT_LE((analytic.v0 - differences.v0).norm(), 1e-10);
  EXPECT_LE(analytic.sweeps * 4, differences.sweeps) << analytic.message << "\n" << differences.message;
}

TEST(TransportedScheme, FailuresAreReportedNotHidden) {
  auto problem = paper_oscillator(0.5, 100, 12);
  const auto limited = transported::solve_shooting(problem, {.tolerance = 1e-12, .max_iterations = 2});
  EXPECT_FALSE(limited.converged());
  EXPECT_EQ(limited.status, Status::MaxIterations);
  EXPECT_NE(limited.message.find("|r| = "), std::string::npos) << limited.message;
  EXPECT_EQ(limited.inner_iterations, 2);
  const auto two_level = transported::solve_two_level(problem, {.max_outer = 1});
  EXPECT_FALSE(two_level.converged());
  EXPECT_NE(two_level.message.find("outer"), std::string::npos) << two_level.message;
}

/// The rigid body with a defect in one callback: `broken` returns NaN once the body has turned
/// away from the identity (g(0, 0) < 0.99), from finite arguments.
struct DefectiveBody {
  mechanics::RigidBody body;
  std::string broken;
  double value(double t, const Eigen::Matrix3d& g, const Eigen::Vector3d& v) const { return body.value(t, g, v); }
  Eigen::Vector3d momentum(double t, const Eigen::Matrix3d& g, const Eigen::Vector3d& v) const {
    return spoil("momentum", g, body.momentum(t, g, v));
  }
  Eigen::Vector3d group_gradient(double t, const Eigen::Matrix3d& g, const Eigen::Vector3d& v) const {
    return spoil("group_gradient", g, body.group_gradient(t, g, v));
  }
  Eigen::Vector3d velocity(double t, const Eigen::Matrix3d& g, const Eigen::Vector3d& mu) const {
    return spoil("velocity", g, body.velocity(t, g, mu));
  }
  Eigen::Vector3d spoil(const std::string& name, const Eigen::Matrix3d& g, Eigen::Vector3d x) const {
    if (name == broken && g(0, 0) < 0.99) x[1] = std::numeric_limits<double>::quiet_NaN();
    return x;
  }
};

// A C++ model's non-finite value from finite arguments is reported at once, naming the callback
// (not left to the solvers: continuation in T would halve T eight times first).
TEST(TransportedScheme, NonFiniteCallbackValuesAreNamedAtOnce) {
  const auto free_body = paper_free_body(0.5, 200, 5);
  for (const std::string name : {"group_gradient", "velocity"}) {
    const transported::TransportedProblem<groups::SO3, DefectiveBody> problem{
        {free_body.lagrangian, name}, 0.5, free_body.T, free_body.N, free_body.g0, free_body.gT};
    expect_invalid([&] { transported::solve_shooting(problem); }, "lagrangian." + name + " returned a non-finite value at t = ");
    expect_invalid([&] { transported::solve_continuation_in_T(problem); }, "lagrangian." + name + " returned a non-finite");
  }
  // Overflow on a diverging iterate (arguments beyond 1e100) is no defect of the model.
  const Eigen::Vector3d huge(1e200, 0, 0), finite(1, 2, 3), overflowed(std::numeric_limits<double>::infinity(), 0, 0);
  const Eigen::Matrix3d g = Eigen::Matrix3d::Identity();
  EXPECT_EQ(mechanics::require_finite_result(overflowed, "lagrangian.momentum", 0.0, g, huge), overflowed);
  EXPECT_THROW(mechanics::require_finite_result(overflowed, "lagrangian.momentum", 0.0, g, finite), ModelError);
  EXPECT_EQ(mechanics::require_finite_result(finite, "lagrangian.momentum", 0.0, g, finite), finite);
}

TEST(TransportedScheme, RejectsBadProblems) {
  auto bad_step = paper_free_body(0.5, 10);
  bad_step.T = -2;
  expect_invalid([&] { transported::TransportedScheme<groups::SO3, mechanics::RigidBody>(bad_step, transported::SchemeOrder::First); }, "T = -2");
  expect_invalid([&] { transported::TransportedScheme<groups::SO3, mechanics::RigidBody>(paper_free_body(0.5, 10), transported::SchemeOrder{3}); }, "order = 3");
  auto problem = paper_free_body(0.5, 10);
  problem.T = 0;
  EXPECT_THROW(transported::solve_shooting(problem), std::invalid_argument);
  problem = paper_free_body(0.5, 10);
  problem.N = 0;
  EXPECT_THROW(transported::solve_two_level(problem), std::invalid_argument);
  problem = paper_free_body(std::nan(""), 10);
  EXPECT_THROW(transported::solve_shooting(problem), std::invalid_argument);
  problem = paper_free_body(0.5, 10);
  problem.gT(0, 0) = 2;
  try {
    transported::solve_shooting(problem);
    ADD_FAILURE() << "non-rotation gT accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gT = "), std::string::npos) << e.what();
  }
  EXPECT_THROW(transported::solve_shooting(paper_free_body(0.5, 10), {.tolerance = 0}), std::invalid_argument);
  EXPECT_THROW(transported::solve_two_level(paper_free_body(0.5, 10), {.tolerance = -1}), std::invalid_argument);
}

}  // namespace
}  // namespace cartan::testing
