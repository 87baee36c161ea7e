// The general transported-velocity solver (include/cartan/general) against independent results:
// the Lie-group Cartan–Schouten solver on the same discrete equations, the same problem without
// the constant-components fast path, Newton's equations in flat R^m (closed form), the classical
// spherical pendulum (an independent Runge–Kutta integration), the classical free rigid body
// under the Levi-Civita connection of its inertia, and energy conservation for any connection.
// The problems go behind the erased Lagrangian (erased(problem)) to the library's compiled solvers
// (kernels/manifold/compiled.hpp), which one test compares with the typed instantiation.

#include <cmath>
#include <numbers>

#include "cartan/kernels/manifold/action.hpp"
#include "cartan/kernels/manifold/compiled.hpp"  // the erased Lagrangian's compiled instantiations
#include "cartan/methods/solve.hpp"     // solvers::detail::continue_in_T on the general family
#include "cartan/manifolds/euclidean.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/methods/lie_group/solve.hpp"  // the Lie-group solve, instantiated in the library
#include "general_cases.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

using namespace cartan::general;
using manifolds::GroupManifold;
using SO3Manifold = GroupManifold<groups::SO3>;

/// The Lie-group Cartan–Schouten solver's shooting (the reference).
transported::TransportedSolution<groups::SO3> reference_solve(
    const transported::TransportedProblem<groups::SO3, mechanics::RigidBody>& problem, SchemeOrder order) {
  cartan::SolveOptions options;
  options.method = cartan::Method::Shooting;
  options.order = order;
  options.tol = 1e-12;
  return transported::solve(problem, options);
}


// A Lie group with alpha = lambda ad given as a general connection solves the same discrete
// equations as the Cartan–Schouten solver (E_k = Ad(h_k), xi = C(Xi)): both converge to
// |r| <= 1e-12, so the curves agree to ~1e-10 (the roots' sensitivity is O(1) here).
TEST(GeneralSolver, CartanSchoutenAsAGeneralConnectionReproducesTheLambdaSolver) {
  for (const auto order : {SchemeOrder::First, SchemeOrder::Second}) {
    const double lambda = 0.3;
    const auto reference_problem = paper_free_body(lambda, 200, 5);
    const auto reference = reference_solve(reference_problem, order);
    ASSERT_TRUE(reference.converged()) << reference.message;
    const auto general = solve_general_shooting(erased(free_body_on(SO3Manifold::cartan_schouten(lambda), reference_problem)),
                                                {.order = order, .tolerance = 1e-12});
    ASSERT_TRUE(general.converged()) << general.message;
    EXPECT_NE(general.message.find("constant frame components"), std::string::npos);
    EXPECT_NEAR_MATRIX(general.v0, reference.v0, 1e-9);
    for (std::size_t k = 0; k < reference.trajectory.g.size(); k += 20) {
      EXPECT_NEAR_MATRIX(general.trajectory.q[k], reference.trajectory.g[k], 1e-9);
      EXPECT_NEAR_MATRIX(general.trajectory.mu[k], reference.trajectory.mu[k], 1e-9);
    }
  }
}

// The general path (frame components recomputed at every node from Gamma) gives the fast path's
// solution where the components are constant.
TEST(GeneralSolver, RecomputedFrameComponentsAgreeWithTheFastPath) {
  const auto p = paper_free_body(0.3, 100, 5);
  const auto fast = solve_general_shooting(erased(free_body_on(SO3Manifold::cartan_schouten(0.3), p)), {.tolerance = 1e-12});
  const auto slow = solve_general_shooting(
      free_body_on(WithoutFastPath<SO3Manifold>{SO3Manifold::cartan_schouten(0.3)}, p), {.tolerance = 1e-12});
  ASSERT_TRUE(fast.converged() && slow.converged()) << fast.message << " / " << slow.message;
  EXPECT_EQ(slow.message.find("constant frame components"), std::string::npos);
  EXPECT_NEAR_MATRIX(fast.v0, slow.v0, 1e-10);
  EXPECT_NEAR_MATRIX(fast.Xi0, slow.Xi0, 1e-9);
}

// Flat, torsion-free R^2 with l = 1/2 |v|^2 - k/2 |q|^2: Newton's equations, whose solution through
// q0, qT is q(t) = q0 cos wt + c sin wt. v0 = w c, reached at the scheme's order.
TEST(GeneralSolver, FlatEuclideanSpaceGivesNewtonsEquationsAtTheSchemesOrder) {
  using R2 = manifolds::Euclidean<2>;
  const double k = 2.0, w = std::sqrt(k), T = 1.3;
  const Eigen::Vector2d q0(0.4, -0.2), qT(-0.3, 0.5);
  const Eigen::Vector2d exact_v0 = w * (qT - q0 * std::cos(w * T)) / std::sin(w * T);
  const KineticPotential<R2> lagrangian(
      Eigen::Matrix2d::Identity(), [k](const Eigen::Vector2d& q) { return k / 2 * q.squaredNorm(); },
      [k](const Eigen::Vector2d& q) { return Eigen::Vector2d(k * q); });
  for (const auto order : {SchemeOrder::First, SchemeOrder::Second}) {
    double errors[2];
    for (int refinement = 0; refinement < 2; ++refinement) {
      const int N = 200 << refinement;
      const auto s = solve_general_shooting(erased(GeneralProblem<R2, KineticPotential<R2>>{R2(), lagrangian, T, N, q0, qT, std::nullopt}),
                                            {.order = order, .tolerance = 1e-13});
      ASSERT_TRUE(s.converged()) << s.message;
      errors[refinement] = (s.v0 - exact_v0).norm();
    }
    const double expected_ratio = order == SchemeOrder::First ? 2.0 : 4.0;
    EXPECT_NEAR(errors[0] / errors[1], expected_ratio, 0.15 * expected_ratio) << "order " << static_cast<int>(order);
  }
}


// For l = 1/2 v^T A v - V(q), 1/2 v^T A v + V is conserved for every connection: the torsion and
// curvature terms of mu' vanish against v by antisymmetry (docs/general-connections.md#energy).
// Checked on R^3 with random constant Christoffel symbols (torsion, curvature, nabla R != 0) and
// an anisotropic A: the drift falls at the scheme's order.
TEST(GeneralSolver, EnergyIsConservedForAnyConnectionAtTheSchemesOrder) {
  using R3 = manifolds::Euclidean<3>;
  std::mt19937 rng(kSeed);
  R3::Coefficients c;
  for (auto& g : c) g = random_vector<Eigen::Matrix<double, 9, 1>>(rng, 0.4).reshaped(3, 3);
  const R3 manifold(c);
  ASSERT_FALSE(manifold.has_parallel_torsion_and_curvature());
  const KineticPotential<R3> lagrangian(
      Eigen::Vector3d(1, 2, 3).asDiagonal(), [](const Eigen::Vector3d& q) { return 0.5 * q.squaredNorm() + q[0]; },
      [](const Eigen::Vector3d& q) { return Eigen::Vector3d(q + Eigen::Vector3d::UnitX()); });
  for (const auto order : {SchemeOrder::First, SchemeOrder::Second}) {
    double drift[2];
    for (int refinement = 0; refinement < 2; ++refinement) {
      const auto problem = erased(GeneralProblem<R3, KineticPotential<R3>>{
          manifold, lagrangian, 1.5, 200 << refinement, Eigen::Vector3d(0.2, 0.1, -0.3), Eigen::Vector3d(1.0, -0.5, 0.4),
          std::nullopt});
      const auto s = solve_general_shooting(problem, {.order = order, .tolerance = 1e-13});
      ASSERT_TRUE(s.converged()) << s.message;
      drift[refinement] = energy_drift(s, lagrangian);
    }
    // At least the scheme's order (measured: 2.0 at order 1; 8.0 at order 2, the drift of the
    // Heun scheme is O(h^3) on this problem).
    const double expected_ratio = order == SchemeOrder::First ? 2.0 : 4.0;
    EXPECT_GT(drift[0] / drift[1], 0.85 * expected_ratio) << "order " << static_cast<int>(order);
  }
}

// The spherical pendulum: on S^2 with its Levi-Civita connection and l = 1/2 |v|^2 - G z the
// transported action is the classical one, so the solution is the classical pendulum. From the
// solver's q0 and q'(0) = E0 v0, an independent RK4 integration of q'' = -G (e_z - z q) - |q'|^2 q
// reaches qT, up to the scheme's error in v0 (order 2 at N = 400: ~1e-5).
TEST(GeneralSolver, SphericalPendulumIsTheClassicalOne) {
  using S2 = manifolds::Sphere;
  const double G = 9.81, T = 1.0;
  const Eigen::Vector3d q0 = manifolds::sphere_point({1, 0, -0.3}), qT = manifolds::sphere_point({0, 1, -0.5});
  const auto lagrangian = KineticPotential<S2>::with_linear_potential(Eigen::Matrix2d::Identity(), Eigen::Vector3d(0, 0, G));
  double miss[2];
  for (int refinement = 0; refinement < 2; ++refinement) {
    const auto problem = erased(GeneralProblem<S2, KineticPotential<S2>>{S2{}, lagrangian, T, 200 << refinement, q0, qT, std::nullopt});
    const auto s = solve_general_shooting(problem, {.order = SchemeOrder::Second, .tolerance = 1e-12});
    ASSERT_TRUE(s.converged()) << s.message;
    miss[refinement] = (spherical_pendulum_endpoint(q0, problem.initial_frame() * s.v0, G, T) - qT).norm();
  }
  EXPECT_LT(miss[1], 1e-4);
  EXPECT_NEAR(miss[0] / miss[1], 4.0, 0.8);
}

// The default frame turns with the endpoints (docs/general-connections.md#frames): an isometry R
// of S^2 or H^2 maps step, transport and difference of (q0, qT) onto those of (R q0, R qT), and the
// frame towards qT onto the frame towards R qT, so with an anisotropic A (a Lagrangian that sees
// the frame) the solution for (R q0, R qT) is R times the solution for (q0, qT) with the same v.
// Both shooting solves converge to 1e-12; v0 and the points agree to ~1e-10 (the Jacobian's
// conditioning times that). The axes' tangent_basis(q0), the default before, gave v0 differing
// by O(1) for the same problem turned.
TEST(GeneralSolver, TheDefaultFrameTurnsWithTheEndpoints) {
  const auto turned = [](const auto& space, const Eigen::Vector3d& q0, const Eigen::Vector3d& qT,
                         const Eigen::Matrix3d& R) {
    using Q = std::decay_t<decltype(space)>;
    const KineticPotential<Q> lagrangian(Eigen::Vector2d(1, 2.5).asDiagonal());
    const auto solve = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      const auto s = solve_general_shooting(erased(GeneralProblem<Q, KineticPotential<Q>>{space, lagrangian, 1.2, 100, a, b, std::nullopt}),
                                            {.order = SchemeOrder::Second, .tolerance = 1e-12});
      EXPECT_TRUE(s.converged()) << s.message;
      return s;
    };
    const auto s = solve(q0, qT), r = solve(R * q0, R * qT);
    EXPECT_NEAR_MATRIX(r.v0, s.v0, 1e-9);
    double gap = 0;
    for (std::size_t k = 0; k < s.trajectory.q.size(); ++k) gap = std::max(gap, (r.trajectory.q[k] - R * s.trajectory.q[k]).norm());
    EXPECT_LT(gap, 1e-9);
  };
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  turned(manifolds::Sphere{}, manifolds::sphere_point({1, 0, 0.2}), manifolds::sphere_point({0, 0.6, -0.8}), rotation);
  Eigen::Matrix3d boost = Eigen::Matrix3d::Identity();  // a Lorentz boost in (x, z) preserves J = diag(1, 1, -1)
  boost(0, 0) = boost(2, 2) = std::cosh(0.6);
  boost(0, 2) = boost(2, 0) = std::sinh(0.6);
  turned(manifolds::HyperbolicPlane{}, manifolds::hyperbolic_point(0.3, -0.2), manifolds::hyperbolic_point(-0.5, 0.7),
         Eigen::Matrix3d(Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitZ()).toRotationMatrix() * boost));
}

// SO(3) with the Levi-Civita connection of the metric I and l = 1/2 v . I v: transport is an
// isometry of I, the action is the classical one, and the curve is the classical free rigid
// body, the lambda = 0 solution (at t = 0 both transported velocities are the body velocity).
// Order 2: the two v0 differ by O(h^2), falling 4x with h.
TEST(GeneralSolver, LeviCivitaOfTheInertiaGivesTheClassicalFreeRigidBody) {
  double gap[2];
  for (int refinement = 0; refinement < 2; ++refinement) {
    const auto p = paper_free_body(0.0, 100 << refinement, 5);
    const auto classical = reference_solve(p, SchemeOrder::Second);
    const auto lc = solve_general_shooting(erased(free_body_on(SO3Manifold::levi_civita(paper_inertia()), p)),
                                           {.order = SchemeOrder::Second, .tolerance = 1e-12});
    ASSERT_TRUE(classical.converged() && lc.converged()) << classical.message << " / " << lc.message;
    gap[refinement] = (lc.v0 - classical.v0).norm();
  }
  EXPECT_LT(gap[1], 1e-3);
  EXPECT_NEAR(gap[0] / gap[1], 4.0, 0.8);
}

// general::solve: the default strategy starts with shooting; continuation in T reaches the same
// solution through shorter horizons (same step h), naming its path; methods of the Lie-group
// solver only are refused by name.
TEST(GeneralSolve, DefaultShootingAndContinuationInTAgree) {
  using S2 = manifolds::Sphere;
  const auto lagrangian = KineticPotential<S2>::with_linear_potential(Eigen::Vector2d(1, 3).asDiagonal(), Eigen::Vector3d(0, 0, 2));
  const GeneralProblem<S2, KineticPotential<S2>> typed{S2{}, lagrangian, 1.5, 300, manifolds::sphere_point({1, 0, 0.2}),
                                                       manifolds::sphere_point({0, 1, -0.3}), std::nullopt};
  const auto problem = erased(typed);  // the library's compiled solvers (kernels/manifold/compiled.hpp)
  const auto direct = solve(problem);
  ASSERT_TRUE(direct.converged()) << direct.message;
  EXPECT_EQ(direct.branch, "shooting (direct from the geodesic guess)");  // the default strategy's words
  // The typed shooting (instantiated here for KineticPotential) is the compiled one without the
  // indirect calls: the same operations in the same order, so the same iterates (to rounding,
  // 1e-14 relative, in case two compilations order a sum differently).
  const auto with_type = solve_general_shooting(typed, {.tolerance = 1e-10});
  const auto through_erasure = solve_general_shooting(problem, {.tolerance = 1e-10});
  ASSERT_TRUE(with_type.converged()) << with_type.message;
  EXPECT_EQ(with_type.inner_iterations, through_erasure.inner_iterations);
  EXPECT_EQ(with_type.sweeps, through_erasure.sweeps);
  EXPECT_NEAR_MATRIX(with_type.v0, through_erasure.v0, 1e-14 * with_type.v0.norm());
  EXPECT_NEAR_MATRIX(with_type.trajectory.q.back(), through_erasure.trajectory.q.back(), 1e-14);
  cartan::SolveOptions options;
  options.method = cartan::Method::Shooting;
  options.continuation = cartan::Continuation::None;
  const auto from_guess = solve(problem, options, GeneralGuess<S2>{direct.v0, direct.Xi0, std::nullopt});
  EXPECT_EQ(from_guess.branch, "direct from the given guess");
  EXPECT_LE(from_guess.inner_iterations, 2);
  options.continuation = cartan::Continuation::T;
  GeneralShootingOptions one_iteration;
  one_iteration.max_iterations = 1;
  const auto failed = solve_general_shooting(problem, one_iteration);  // the path's failed direct attempt
  ASSERT_FALSE(failed.converged());
  auto path_copy = failed;  // the path moves from it
  const auto continued = cartan::solvers::detail::continue_in_T(
      problem, cartan::ContinuationOptions{.shooting = {.tolerance = 1e-10}}, std::nullopt, std::nullopt, &path_copy);
  ASSERT_TRUE(continued.converged()) << continued.message;
  EXPECT_EQ(continued.branch.rfind("continued in T from T = 0.75", 0), 0u) << continued.branch;
  EXPECT_GT(continued.inner_iterations, failed.inner_iterations);  // summed along the path (D8)
  EXPECT_NEAR_MATRIX(continued.v0, direct.v0, 1e-8);
  options.method = cartan::Method::MultipleShooting;
  options.continuation = cartan::Continuation::None;
  expect_invalid([&] { solve(problem, options); }, {"multiple-shooting", "not available for a general connection"});
  options.method = cartan::Method::Shooting;
  options.continuation = cartan::Continuation::Lambda;
  expect_invalid([&] { solve(problem, options); }, "continuation = lambda");
}

/// max over smooth endpoint-fixed variations q_k -> step(q_k, e w(t_k)) of |dS_h/de| for the
/// discrete transported action (kernels/manifold/action.hpp: uses no part of the scheme), relative to
/// sum_k h |l_k|, the size of the action's terms.
template <class M, class L>
double action_stationarity(const GeneralProblem<M, L>& p, const GeneralSolution<M>& s) {
  const double h = p.step();
  double size = 0, worst = 0;
  for (std::size_t k = 0; k + 1 < s.trajectory.q.size(); ++k) size += h * std::abs(p.lagrangian.value(0, s.trajectory.q[k], s.trajectory.v[k]));
  for (int mode = 1; mode <= 3; ++mode) {
    for (int direction = 0; direction < M::kDim; ++direction) {
      std::vector<manifolds::VectorOf<M>> w(s.trajectory.q.size(), manifolds::VectorOf<M>::Zero());
      for (std::size_t k = 1; k + 1 < w.size(); ++k) {
        w[k] = p.manifold.tangent_basis(s.trajectory.q[k]).col(direction) * std::sin(mode * std::numbers::pi * s.trajectory.t[k] / p.T);
      }
      worst = std::max(worst, std::abs(discrete_action_derivative(p, s.trajectory.q, w)));
    }
  }
  return worst / size;
}

// Genuinely new dynamics (a Lagrangian that sees the direction of v): the solver's curves make an
// independent discrete transported action stationary, to the scheme's order: the order-2 figure
// falls 4x when h halves (the order-1 one 2x). On S^2 with A = diag(1, 3) and gravity, and on SO(3)
// with l = 1/2 v.J v under the Levi-Civita connection of the metric diag(1, 2, 3) != J = diag(2, 3, 4).
TEST(GeneralSolver, NewDynamicsMakeAnIndependentDiscreteActionStationaryAtTheSchemesOrder) {
  using S2 = manifolds::Sphere;
  const auto sphere_problem = [](int N) {
    return erased(GeneralProblem<S2, KineticPotential<S2>>{
        S2{}, KineticPotential<S2>::with_linear_potential(Eigen::Vector2d(1, 3).asDiagonal(), Eigen::Vector3d(0, 0, 2)),
        1.2, N, manifolds::sphere_point({1, 0, 0.2}), manifolds::sphere_point({0, 1, -0.3}), std::nullopt});
  };
  const auto so3_problem = [](int N) {
    const auto p = paper_free_body(0.0, N, 3);
    return erased(GeneralProblem<SO3Manifold, KineticPotential<SO3Manifold>>{
        SO3Manifold::levi_civita(Eigen::Vector3d(1, 2, 3).asDiagonal()), KineticPotential<SO3Manifold>(paper_inertia()),
        p.T, p.N, p.g0, p.gT, std::nullopt});
  };
  for (const auto order : {SchemeOrder::First, SchemeOrder::Second}) {
    const double expected = order == SchemeOrder::First ? 2.0 : 4.0;
    double sphere[2], so3[2];
    for (int r = 0; r < 2; ++r) {
      const auto ps = sphere_problem(100 << r);
      const auto ss = solve_general_shooting(ps, {.order = order, .tolerance = 1e-13});
      const auto pg = so3_problem(100 << r);
      const auto sg = solve_general_shooting(pg, {.order = order, .tolerance = 1e-13});
      ASSERT_TRUE(ss.converged() && sg.converged()) << ss.message << " / " << sg.message;
      sphere[r] = action_stationarity(ps, ss);
      so3[r] = action_stationarity(pg, sg);
    }
    EXPECT_NEAR(sphere[0] / sphere[1], expected, 0.25 * expected) << sphere[0] << " " << sphere[1];
    EXPECT_NEAR(so3[0] / so3[1], expected, 0.25 * expected) << so3[0] << " " << so3[1];
  }
}

// verify_general passes honest solutions (both orders, a curved and a group manifold, a connection
// with torsion and curvature) and fails a solution checked against another problem: another
// gravity, another connection. Figures / rho^p are printed to calibrate against docs/verify.md.
TEST(GeneralVerify, PassesSolutionsAndFailsThemAgainstAnotherProblem) {
  using S2 = manifolds::Sphere;
  using R3 = manifolds::Euclidean<3>;
  const auto sphere = [](double gravity, int N) {
    return erased(GeneralProblem<S2, KineticPotential<S2>>{
        S2{}, KineticPotential<S2>::with_linear_potential(Eigen::Vector2d(1, 3).asDiagonal(), Eigen::Vector3d(0, 0, gravity)),
        1.2, N, manifolds::sphere_point({1, 0, 0.2}), manifolds::sphere_point({0, 1, -0.3}), std::nullopt});
  };
  const auto so3 = [](const SO3Manifold& manifold) {
    const auto p = paper_free_body(0.0, 200, 3);
    return erased(GeneralProblem<SO3Manifold, KineticPotential<SO3Manifold>>{
        manifold, KineticPotential<SO3Manifold>(paper_inertia()), p.T, p.N, p.g0, p.gT, std::nullopt});
  };
  std::mt19937 rng(kSeed);
  R3::Coefficients c;
  for (auto& g : c) g = random_vector<Eigen::Matrix<double, 9, 1>>(rng, 0.4).reshaped(3, 3);
  const auto flat = erased(GeneralProblem<R3, KineticPotential<R3>>{
      R3(c), KineticPotential<R3>(Eigen::Vector3d(1, 2, 3).asDiagonal(), [](const Eigen::Vector3d& q) { return 0.5 * q.squaredNorm(); },
                                  [](const Eigen::Vector3d& q) { return Eigen::Vector3d(q); }),
      1.5, 300, Eigen::Vector3d(0.2, 0.1, -0.3), Eigen::Vector3d(1.0, -0.5, 0.4), std::nullopt});
  const auto report_of = [](const auto& problem, const auto& solution, double tol) {
    const verify::Report r = verify_general(problem, solution.trajectory, solution.order, tol, solution.status);
    std::printf("%s", r.text().c_str());
    return r;
  };
  for (const auto order : {SchemeOrder::First, SchemeOrder::Second}) {
    const GeneralShootingOptions options{.order = order, .tolerance = 1e-11};
    const auto s = solve_general_shooting(sphere(2, 200), options);
    ASSERT_TRUE(s.converged()) << s.message;
    EXPECT_TRUE(report_of(sphere(2, 200), s, 1e-11).passed());
    EXPECT_FALSE(report_of(sphere(2.5, 200), s, 1e-11).passed());  // another gravity
    const auto lc = so3(SO3Manifold::levi_civita(Eigen::Vector3d(1, 2, 3).asDiagonal()));
    const auto g = solve_general_shooting(lc, options);
    ASSERT_TRUE(g.converged()) << g.message;
    EXPECT_TRUE(report_of(lc, g, 1e-11).passed());
    EXPECT_FALSE(report_of(so3(SO3Manifold::cartan_schouten(0.3)), g, 1e-11).passed());  // another connection
    const auto f = solve_general_shooting(flat, options);
    ASSERT_TRUE(f.converged()) << f.message;
    EXPECT_TRUE(report_of(flat, f, 1e-11).passed());
  }
  auto failed = solve_general_shooting(sphere(2, 200), {.tolerance = 1e-11, .max_iterations = 1});
  ASSERT_FALSE(failed.converged());
  EXPECT_FALSE(report_of(sphere(2, 200), failed, 1e-11).passed());
}

TEST(GeneralSolver, BadInputIsRejectedWithTheValue) {
  using S2 = manifolds::Sphere;
  const auto l = KineticPotential<S2>(Eigen::Matrix2d::Identity());
  const Eigen::Vector3d q = Eigen::Vector3d::UnitZ();
  expect_invalid([&] { solve_general_shooting(erased(GeneralProblem<S2, KineticPotential<S2>>{S2{}, l, -1, 10, q, q, std::nullopt})); }, "T = -1");
  expect_invalid([&] { solve_general_shooting(erased(GeneralProblem<S2, KineticPotential<S2>>{S2{}, l, 1, 10, Eigen::Vector3d(1, 1, 1), q, std::nullopt})); }, "q0");
  Eigen::Matrix<double, 3, 2> off;
  off << 1, 0, 0, 1, 0.5, 0;  // not tangent at the north pole
  expect_invalid([&] { solve_general_shooting(erased(GeneralProblem<S2, KineticPotential<S2>>{S2{}, l, 1, 10, q, q, off})); }, "frame0");
  expect_invalid([] { KineticPotential<S2>(Eigen::Vector2d(1, -1).asDiagonal()); }, {"inertia", "positive definite"});
  // A hand-written Lagrangian whose velocity does not invert its momentum (here off by 1e-4 in one
  // component: a wrong answer that would converge) is refused before any work, as by the
  // Lie-group solve (D11).
  struct BrokenInverse {
    KineticPotential<S2> kinetic{Eigen::Matrix2d::Identity()};
    double value(double t, const Eigen::Vector3d& x, const Eigen::Vector2d& v) const { return kinetic.value(t, x, v); }
    Eigen::Vector2d momentum(double t, const Eigen::Vector3d& x, const Eigen::Vector2d& v) const {
      return kinetic.momentum(t, x, v);
    }
    Eigen::Vector2d velocity(double t, const Eigen::Vector3d& x, const Eigen::Vector2d& mu) const {
      return kinetic.velocity(t, x, mu) + Eigen::Vector2d(1e-4, 0);
    }
    Eigen::Vector3d point_gradient(double t, const Eigen::Vector3d& x, const Eigen::Vector2d& v) const {
      return kinetic.point_gradient(t, x, v);
    }
  };
  const Eigen::Vector3d east = Eigen::Vector3d::UnitX();
  const auto broken = erased(GeneralProblem<S2, BrokenInverse>{S2{}, BrokenInverse{}, 1, 10, q, east, std::nullopt});
  expect_invalid([&] { solve(broken, cartan::SolveOptions{}); },
                 {"general::solve: lagrangian = (velocity(t, g, momentum(t, g, v))", "does not invert its momentum"});
  // The same Lagrangian with its inverse exact is solved.
  const auto kinetic = erased(GeneralProblem<S2, KineticPotential<S2>>{S2{}, l, 1, 10, q, east, std::nullopt});
  EXPECT_TRUE(solve(kinetic, cartan::SolveOptions{}).converged());
}

}  // namespace
}  // namespace cartan::testing
