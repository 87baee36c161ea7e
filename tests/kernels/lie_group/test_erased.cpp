// The erased Lagrangian (mechanics/erased_lagrangian.hpp) and the library's solve and verify for it
// (kernels/lie_group/compiled.hpp, compiled in src/methods/lie_group/erased_*.cpp) against the typed
// instantiations of the same models: every evaluation forwarded unchanged, the same solution on each
// shipped group and by each method, and the same verification figures.

#include <random>

#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/lie_group/verify.hpp"  // verify_trajectory typed, to compare with the erased one
#include "paper_cases.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

using transported::erased;
using transported::Method;
using transported::SolveOptions;

// Forwarding is exact: the erased type calls the model's own members (its Hessian: the model's
// analytic one where it has it, lagrangian_hessian's otherwise), so the values are bit for bit equal.
TEST(ErasedLagrangian, ForwardsEveryEvaluationUnchanged) {
  std::mt19937 rng(kSeed);
  const mechanics::SO3Oscillator model(paper_inertia());
  const mechanics::ErasedLagrangian<groups::SO3> erased_model(model);
  for (int k = 0; k < 5; ++k) {
    const double t = 0.1 * k;
    const auto g = random_element<groups::SO3>(rng);
    const auto v = random_tangent<groups::SO3>(rng);
    EXPECT_EQ(erased_model.value(t, g, v), model.value(t, g, v));
    EXPECT_EQ(erased_model.momentum(t, g, v), model.momentum(t, g, v));
    EXPECT_EQ(erased_model.group_gradient(t, g, v), model.group_gradient(t, g, v));
    EXPECT_EQ(erased_model.velocity(t, g, v), model.velocity(t, g, v));
    const auto expected = mechanics::lagrangian_hessian<groups::SO3>(model, t, g, v);
    const auto h = erased_model.hessian(t, g, v);
    EXPECT_EQ(h.momentum_v, expected.momentum_v);
    EXPECT_EQ(h.momentum_g, expected.momentum_g);
    EXPECT_EQ(h.gradient_v, expected.gradient_v);
    EXPECT_EQ(h.gradient_g, expected.gradient_g);
  }
  // An erased Lagrangian (or a type derived from it) is copied, not wrapped again: the copy
  // shares the model.
  const mechanics::ErasedLagrangian<groups::SO3> copy(erased_model);
  EXPECT_EQ(copy.value(0.2, groups::SO3::identity(), Eigen::Vector3d(1, 2, 3)),
            model.value(0.2, groups::SO3::identity(), Eigen::Vector3d(1, 2, 3)));
}

/// Shooting of `problem` as its own type and behind the erased type. Both stop at a terminal
/// residual of at most 1e-12 on the same discrete equations (the Jacobians may differ: the typed
/// one uses the model's HessianStructure), and the map v0 -> residual is well conditioned on these
/// short horizons, so v0 agrees to 1e-9 and every node to the same.
template <groups::LieGroup G, class L>
void expect_erased_solves_as_typed(const transported::TransportedProblem<G, L>& problem) {
  SolveOptions options;
  options.method = Method::Shooting;
  options.tol = 1e-12;
  const auto typed = transported::solve(problem, options);
  const auto through_erased = transported::solve(erased(problem), options);
  ASSERT_TRUE(typed.converged()) << typed.message;
  ASSERT_TRUE(through_erased.converged()) << through_erased.message;
  EXPECT_NEAR_MATRIX(through_erased.v0, typed.v0, 1e-9);
  ASSERT_EQ(through_erased.trajectory.g.size(), typed.trajectory.g.size());
  for (std::size_t k = 0; k < typed.trajectory.g.size(); k += 10) {
    EXPECT_NEAR_MATRIX(through_erased.trajectory.g[k], typed.trajectory.g[k], 1e-9);
    EXPECT_NEAR_MATRIX(through_erased.trajectory.mu[k], typed.trajectory.mu[k], 1e-9);
  }
  EXPECT_NEAR(through_erased.action, typed.action, 1e-9 * (1 + std::abs(typed.action)));
}

TEST(ErasedLagrangian, SolvesAsTheTypedModelOnEveryShippedGroup) {
  for (const double lambda : {0.0, 0.3, 1.0}) {
    expect_erased_solves_as_typed(paper_free_body(lambda, 100, 5));
    expect_erased_solves_as_typed(paper_oscillator(lambda, 100, 3));
    expect_erased_solves_as_typed(transported::TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator>{
        mechanics::h3_oscillator(), lambda, 1.0, 40, groups::Heisenberg::Element(0.2, -0.1, 0.3),
        groups::Heisenberg::Element(1.0, 0.5, 0.8)});
    expect_erased_solves_as_typed(transported::TransportedProblem<groups::SE2, mechanics::SE2FreeBody>{
        mechanics::SE2FreeBody(Eigen::Vector3d(2, 1, 3).asDiagonal()), lambda, 2.0, 40, groups::SE2::identity(),
        groups::SE2::exp(Eigen::Vector3d(0.7, 1.0, -0.4))});
    using V6 = Eigen::Matrix<double, 6, 1>;
    expect_erased_solves_as_typed(transported::TransportedProblem<groups::SE3, mechanics::SE3FreeBody>{
        mechanics::SE3FreeBody(V6(1, 2, 3, 4, 4, 4).asDiagonal()), lambda, 2.0, 40, groups::SE3::identity(),
        groups::SE3::exp((V6() << 0.3, -0.2, 0.5, 1.0, 0.4, -0.6).finished())});
  }
}

// Every method of the Lie-group solver is compiled for the erased type and reaches what the
// typed instantiation reaches by the same method: both stop at tolerance 1e-10 on the same
// equations (the default strategy, multiple shooting, and the variational method's discrete
// Euler-Lagrange equations of S_h), so the nodes agree to 1e-8; the two-level scheme stops on the
// change of xi relative to xi_scale, which leaves them within 1e-7.
TEST(ErasedLagrangian, EveryMethodReachesTheTypedSolution) {
  const auto problem = paper_oscillator(0.3, 100, 3);
  for (const Method method : {Method::Auto, Method::MultipleShooting, Method::TwoLevel, Method::Variational}) {
    SolveOptions options;
    options.method = method;
    const auto typed = transported::solve(problem, options);
    const auto s = transported::solve(erased(problem), options);
    ASSERT_TRUE(typed.converged()) << to_string(method) << ": " << typed.message;
    ASSERT_TRUE(s.converged()) << to_string(method) << ": " << s.message;
    EXPECT_EQ(s.method, typed.method) << s.branch;
    const double tolerance = method == Method::TwoLevel ? 1e-7 : 1e-8;
    for (std::size_t k = 0; k < typed.trajectory.g.size(); k += 10) {
      EXPECT_NEAR_MATRIX(s.trajectory.g[k], typed.trajectory.g[k], tolerance) << to_string(method) << " k = " << k;
    }
  }
  // Collocation needs a natural Lagrangian's constant inertia, which the erased type does not
  // promise: refused by name before any work.
  SolveOptions collocation;
  collocation.method = Method::Collocation;
  expect_invalid([&] { (void)transported::solve(erased(problem), collocation); }, "collocation");
}

// verify_trajectory evaluates the Lagrangian only through its members, so the erased type gives the
// typed figures (to rounding in the order of summation, none here: bit for bit in practice).
TEST(ErasedLagrangian, VerifiesAsTheTypedModel) {
  const auto problem = paper_oscillator(0.5, 200, 3);
  const auto s = transported::solve(problem);
  ASSERT_TRUE(s.converged()) << s.message;
  const verify::Report typed = verify::verify_solution(problem, s, 1e-10);
  const verify::Report through_erased = verify::verify_trajectory(erased(problem), s.trajectory, s.order, 1e-10);
  ASSERT_EQ(typed.checks.size(), through_erased.checks.size());
  EXPECT_TRUE(typed.passed());
  for (std::size_t i = 0; i < typed.checks.size(); ++i) {
    EXPECT_EQ(through_erased.checks[i].name, typed.checks[i].name);
    EXPECT_NEAR(through_erased.checks[i].figure, typed.checks[i].figure, 1e-12 * (1 + std::abs(typed.checks[i].figure)))
        << typed.checks[i].name;
    EXPECT_EQ(through_erased.checks[i].passed(), typed.checks[i].passed()) << typed.checks[i].name;
  }
}

}  // namespace
}  // namespace cartan::testing
