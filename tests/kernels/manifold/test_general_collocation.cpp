// Collocation of the continuous general system (include/cartan/methods/manifold/collocation.hpp) against
// independent results: the Lie-group collocation of the Cartan–Schouten problem, the classical
// spherical pendulum (RK4), the limit of the order-2 discrete scheme where the frame components
// vary (nabla R != 0), and energy conservation; and general::solve's use of it.

#include <cmath>

#include "cartan/kernels/manifold/compiled.hpp"  // the library's compiled solvers, through erased(problem)
#include "cartan/manifolds/chart.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/methods/lie_group/solve.hpp"  // the Lie-group solve, instantiated in the library
#include "general_cases.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

using namespace cartan::general;
using manifolds::Sphere;
using SO3Manifold = manifolds::GroupManifold<groups::SO3>;
using cartan::Method;

/// Collocation; with Continuation::T it starts from the order-2 shooting solution when Newton
/// fails from the geodesic guess on the N-interval mesh (methods/manifold/solve.hpp).
cartan::SolveOptions collocation_options(double tol,
                                              cartan::Continuation fallback = cartan::Continuation::None) {
  cartan::SolveOptions options;
  options.method = Method::Collocation;
  options.tol = tol;
  options.continuation = fallback;
  return options;
}

KineticPotential<Sphere> pendulum_lagrangian(const Eigen::Vector2d& a, double G) {
  return KineticPotential<Sphere>::with_linear_potential(a.asDiagonal(), Eigen::Vector3d(0, 0, G));
}

ErasedProblem<Sphere> pendulum(const Eigen::Vector2d& a, double G, double T, int N) {
  return erased(GeneralProblem<Sphere, KineticPotential<Sphere>>{Sphere{}, pendulum_lagrangian(a, G), T, N,
                                                                 manifolds::sphere_point({1, 0, -0.3}),
                                                                 manifolds::sphere_point({0, 1, -0.5}), std::nullopt});
}

// alpha = lambda ad as a general connection: the continuous general system is the continuous
// reduced system (docs/general-connections.md#reduction), so both collocations converge to the
// same solution. Each solves to a relative residual of 1e-9 per interval; the solutions then
// differ from the exact one, and from each other, by a few times that (measured 4e-10).
TEST(GeneralCollocation, CartanSchoutenReproducesTheLieGroupCollocation) {
  const double lambda = 0.3;
  const auto p = paper_free_body(lambda, 50, 5);
  const auto lie = transported::solve(p, collocation_options(1e-9));
  const auto general = solve(erased(free_body_on(SO3Manifold::cartan_schouten(lambda), p)), collocation_options(1e-9));
  ASSERT_TRUE(lie.converged()) << lie.message;
  ASSERT_TRUE(general.converged()) << general.message;
  EXPECT_EQ(general.method, Method::Collocation);
  EXPECT_EQ(general.order, 4);
  ASSERT_TRUE(general.collocation.has_value());
  EXPECT_LE(general.collocation->max_residual, 1e-9);
  EXPECT_NEAR_MATRIX(general.v0, lie.v0, 1e-8);
  EXPECT_NEAR_MATRIX(general.trajectory.q.back(), p.gT, 1e-8);
  EXPECT_LE(general.xi_terminal, 1e-8);
}

// The spherical pendulum (A = I): the continuous solution is the classical one, so the RK4
// integration from (q0, E0 v0) reaches qT up to the collocation's error (tol 1e-10: measured
// 1e-9), far below the order-2 scheme's 1e-5 at N = 400. Gravity pulls the solution far from
// the geodesic guess, where Newton fails: alone, collocation reports that failure; with the
// fallback it starts from the order-2 shooting solution.
TEST(GeneralCollocation, SphericalPendulumIsTheClassicalOne) {
  const double G = 9.81, T = 1.0;
  const auto problem = pendulum({1, 1}, G, T, 40);
  auto options = collocation_options(1e-10, cartan::Continuation::T);
  options.samples = 101;
  const auto s = solve(problem, options);
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_EQ(s.branch.rfind("from the order-2 shooting solution (direct from the geodesic guess)", 0), 0u)
      << s.branch;
  ASSERT_EQ(s.trajectory.t.size(), 101u);
  EXPECT_DOUBLE_EQ(s.trajectory.t.back(), T);
  const Eigen::Vector3d reached = spherical_pendulum_endpoint(problem.q0, problem.initial_frame() * s.v0, G, T);
  EXPECT_LT((reached - problem.qT).norm(), 1e-8);
  // The output stays on S^2 and the frame orthonormal up to the same error.
  for (std::size_t k = 0; k < s.trajectory.q.size(); ++k) {
    EXPECT_NEAR(s.trajectory.q[k].norm(), 1.0, 1e-9);
    EXPECT_NEAR_MATRIX(s.trajectory.frame[k].transpose() * s.trajectory.frame[k], Eigen::Matrix2d::Identity(), 1e-9);
  }
  options.continuation = cartan::Continuation::None;
  options.max_nodes = 400;
  const auto alone = solve(problem, options);
  EXPECT_FALSE(alone.converged());
  EXPECT_EQ(alone.branch, "direct from the geodesic guess on a uniform mesh of N intervals");
}

// Where the frame components vary (the Levi-Civita connection of diag(1, 2, 3) on SO(3), with
// the inertia diag(2, 3, 4): nabla R != 0), the order-2 scheme converges to the continuous
// solution: |v0_N - v0_collocation| falls 4x per halving of h (measured 7.3e-5 and 1.8e-5 at
// N = 100, 200; collocation at tol 1e-10 is within ~1e-8 of the limit).
TEST(GeneralCollocation, TheOrderTwoSchemeConvergesToItWhereTheFrameComponentsVary) {
  const auto manifold = SO3Manifold::levi_civita(Eigen::Vector3d(1, 2, 3).asDiagonal());
  const auto continuous =
      solve(erased(free_body_on(manifold, paper_free_body(0, 40, 3))), collocation_options(1e-10, cartan::Continuation::T));
  ASSERT_TRUE(continuous.converged()) << continuous.message;
  double gap[2];
  for (int refinement = 0; refinement < 2; ++refinement) {
    const auto discrete = solve_general_shooting(erased(free_body_on(manifold, paper_free_body(0, 100 << refinement, 3))),
                                                 {.order = SchemeOrder::Second, .tolerance = 1e-13});
    ASSERT_TRUE(discrete.converged()) << discrete.message;
    EXPECT_EQ(discrete.message.find("constant frame components"), std::string::npos);
    gap[refinement] = (discrete.v0 - continuous.v0).norm();
  }
  EXPECT_NEAR(gap[0] / gap[1], 4.0, 0.6);
}

// l = 1/2 v^T A v - G z with A != I: 1/2 v^T A v + G z is conserved by the exact flow for any
// connection; along the collocation solution it is constant to the tolerance's order.
TEST(GeneralCollocation, ConservesEnergyToTheTolerance) {
  const auto problem = pendulum({1, 2.5}, 3.0, 1.5, 40);
  const auto s = solve(problem, collocation_options(1e-10));
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_LT(energy_drift(s, pendulum_lagrangian({1, 2.5}, 3.0)), 1e-8);
}

// A trajectory guess (here a converged order-2 shooting solution) starts collocation, and is
// checked: times from 0 to T, rows at every time, not together with v0 / Xi0.
TEST(GeneralCollocation, StartsFromATrajectoryAndRejectsABadOne) {
  const auto problem = pendulum({1, 2.5}, 3.0, 1.5, 60);
  const auto shooting = solve_general_shooting(problem, {.order = SchemeOrder::Second, .tolerance = 1e-12});
  ASSERT_TRUE(shooting.converged()) << shooting.message;
  GeneralGuess<Sphere> guess;
  guess.trajectory = shooting.trajectory;
  const auto s = solve(problem, collocation_options(1e-10), guess);
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_EQ(s.branch, "from the given trajectory");
  const auto direct = solve(problem, collocation_options(1e-10));
  EXPECT_NEAR_MATRIX(s.v0, direct.v0, 1e-8);

  auto shorter = guess;  // times from 0 to 1.4, not to T = 1.5
  for (double& t : shorter.trajectory->t) t *= 1.4 / 1.5;
  expect_invalid([&] { solve(problem, collocation_options(1e-10), shorter); }, {"guess.trajectory", "must run from 0 to T = 1.5"});
  auto ragged = guess;
  ragged.trajectory->Xi.pop_back();
  expect_invalid([&] { solve(problem, collocation_options(1e-10), ragged); }, "guess.trajectory");
  auto both = guess;
  both.v0 = shooting.v0;
  expect_invalid([&] { solve(problem, collocation_options(1e-10), both); }, "not both");
}

// A manifold brought by the user as a chart: the Poincare half-plane from its Christoffel field
// alone. With l = 1/2 |v|^2 in a g-orthonormal frame at q0 the solutions are the hyperbolic
// geodesics at constant speed, so |v0| = d(q0, qT) / T with the closed-form distance
// d = arccosh(1 + |qT - q0|^2 / (2 y0 yT)): by collocation to its tolerance, by the order-2 scheme
// at its order (error ratio 4 per halving of h).
TEST(GeneralCollocation, AUserChartSolvesTheHyperbolicGeodesicProblem) {
  using H = manifolds::Chart<2>;
  const Eigen::Vector2d q0(-0.5, 0.8), qT(1.2, 1.6);
  const double T = 2.0, distance = std::acosh(1 + (qT - q0).squaredNorm() / (2 * q0.y() * qT.y()));
  const auto problem = [&](int N) {
    return erased(GeneralProblem<H, KineticPotential<H>>{manifolds::poincare_half_plane(),
                                                         KineticPotential<H>(Eigen::Matrix2d::Identity()), T, N, q0, qT,
                                                         Eigen::Matrix2d(q0.y() * Eigen::Matrix2d::Identity())});
  };
  const auto collocated = solve(problem(20), collocation_options(1e-10));
  ASSERT_TRUE(collocated.converged()) << collocated.message;
  EXPECT_NEAR(collocated.v0.norm(), distance / T, 1e-8);
  double error[2];
  for (int refinement = 0; refinement < 2; ++refinement) {
    const auto s = solve_general_shooting(problem(100 << refinement), {.order = SchemeOrder::Second, .tolerance = 1e-12});
    ASSERT_TRUE(s.converged()) << s.message;
    error[refinement] = std::abs(s.v0.norm() - distance / T);
  }
  EXPECT_NEAR(error[0] / error[1], 4.0, 0.6);
}

}  // namespace
}  // namespace cartan::testing
