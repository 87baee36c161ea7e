// general::solve on a Lie group with the Cartan–Schouten connection runs the Lie-group kernel
// (include/cartan/methods/lie_group_as_manifold.hpp; docs/design/lie-kernel.md) and returns what the general
// kernel (solve_general_shooting) returns at the same discrete solution: the two schemes are the
// same discrete equations (E_k = Ad(h_k), xi = C(Xi)), so the results differ only by where
// Levenberg–Marquardt stops within the tolerance and by rounding. Cases: the SO(3) free body and
// oscillator, the SE(3) free body, the H3 oscillator (where C has rank 2 < 3), at orders 1 and 2,
// each model through OnGroupManifold behind the erased Lagrangian (the library's compiled solve).
//
// Tolerances (theory; design §5.4 for the measured figures):
// * Kernel against kernel, 1e-9 at tol 1e-12: both stop within |r| <= 1e-12 of the same discrete
//   root, whose sensitivity is O(1) to O(100) on these problems (the bound of the existing
//   comparison, GeneralSolver.CartanSchoutenAsAGeneralConnectionReproducesTheLambdaSolver;
//   measured <= 6e-14 for q, v, mu and <= 5e-15 for the frame and Xi).
// * The rebuilt trajectory against a general sweep from its own (v0, Xi0), 1e-11 relative: the same
//   discrete equations from the same start, so only rounding (~1e-16 per step) amplified over N
//   steps separates them (measured 2e-15 to 6e-14). On H3 the central component of xi (constant,
//   at most tol s at the root) has no Xi behind it and adds at most ~T |v| tol s.
// * verify_general: the boundary figure within tol (|r_q| <= tol and |Xi_N| = |C^+ xi_N| <= |xi_N|,
//   every nonzero singular value of C being >= 1); the discretisation figures within 2x of the
//   general kernel's (the same samples to ~1e-13; measured equal to 2 digits), plus 1e-12 for
//   figures at rounding level.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "cartan/kernels/manifold/compiled.hpp"  // the library's compiled solve, shooting and verify
#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/kernels/lie_group/along.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/methods/lie_group_as_manifold.hpp"
#include "cartan/methods/lie_group/solve.hpp"  // the Lie-group solve, instantiated in the library
#include "manifold/general_cases.hpp"
#include "test_support.hpp"

namespace cartan::testing::lie_kernel_tests {

using general::ErasedLagrangian;
using general::ErasedProblem;
using general::GeneralGuess;
using general::GeneralSolution;
using general::GeneralTrajectory;
using manifolds::GroupManifold;
using cartan::Method;
using SO3Manifold = GroupManifold<groups::SO3>;

constexpr double kTol = 1e-12;
constexpr SchemeOrder kOrders[] = {SchemeOrder::First, SchemeOrder::Second};

/// A Lie-group problem of the paper's form as the general problem on GroupManifold<G>::cartan_schouten
/// with the same lambda: the model through OnGroupManifold, behind the erased Lagrangian.
template <groups::LieGroup G, class Model>
ErasedProblem<GroupManifold<G>> on_cartan_schouten(const transported::TransportedProblem<G, Model>& p) {
  using M = GroupManifold<G>;
  return {M::cartan_schouten(p.lambda), ErasedLagrangian<M>(general::OnGroupManifold<G, Model>{p.lagrangian}), p.T,
          p.N, p.g0, p.gT, std::nullopt};
}

transported::TransportedProblem<groups::SE3, mechanics::SE3FreeBody> se3_free_body() {
  using V6 = Eigen::Matrix<double, 6, 1>;
  return {mechanics::SE3FreeBody(V6(1, 1, 1, 2, 3, 4).asDiagonal()), 0.7, 2.0, 100, groups::SE3::identity(),
          groups::SE3::exp((V6() << 0.3, -0.2, 0.5, 1.0, 0.4, -0.6).finished())};
}

transported::TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator> h3_oscillator() {
  return {mechanics::h3_oscillator(), 0.3, 1.5, 100, groups::Heisenberg::Element(0.2, -0.1, 0.3),
          groups::Heisenberg::Element(1.0, 0.5, 0.8)};
}

/// Shooting (no continuation) at `tol` and `order`.
cartan::SolveOptions shooting_options(SchemeOrder order, double tol = kTol) {
  cartan::SolveOptions options;
  options.method = Method::Shooting;
  options.order = order;
  options.tol = tol;
  return options;
}

bool has(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

/// max_k max |a_k - b_k| over the entries, +inf when the lengths differ.
template <class X>
double max_gap(const std::vector<X>& a, const std::vector<X>& b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, max_abs_diff(a[k], b[k]));
  return worst;
}

/// max_k max |a_k - b_k| / (1 + max |b_k|), +inf when the lengths differ.
template <class X>
double relative_gap(const std::vector<X>& a, const std::vector<X>& b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    worst = std::max(worst, max_abs_diff(a[k], b[k]) / (1 + b[k].cwiseAbs().maxCoeff()));
  }
  return worst;
}

/// Every node of two trajectories within `tol` (absolute), field by field.
template <class M>
void expect_same_nodes(const GeneralTrajectory<M>& a, const GeneralTrajectory<M>& b, double tol, const std::string& what) {
  ASSERT_EQ(a.t.size(), b.t.size()) << what;
  EXPECT_LE(max_gap(a.q, b.q), tol) << what << ": q";
  EXPECT_LE(max_gap(a.frame, b.frame), tol) << what << ": frame";
  EXPECT_LE(max_gap(a.v, b.v), tol) << what << ": v";
  EXPECT_LE(max_gap(a.mu, b.mu), tol) << what << ": mu";
  EXPECT_LE(max_gap(a.Xi, b.Xi), tol) << what << ": Xi";
}

/// The four cases at both orders: check(problem, order, name).
template <class Check>
void for_every_case(const Check& check) {
  for (const SchemeOrder order : kOrders) {
    const std::string at = " at order " + std::to_string(static_cast<int>(order));
    check(on_cartan_schouten(paper_free_body(0.3, 200, 5)), order, "SO(3) free body" + at);
    check(on_cartan_schouten(paper_oscillator(0.3, 150, 3)), order, "SO(3) oscillator" + at);
    check(on_cartan_schouten(se3_free_body()), order, "SE(3) free body" + at);
    check(on_cartan_schouten(h3_oscillator()), order, "H3 oscillator" + at);
  }
}

/// C(v mu^T) = ad*_v mu (the map of Xi' = -v mu^T onto xi' = -ad*_v mu, disc-aux); C^+ is the
/// Moore–Penrose inverse, so C C^+ is the identity where C is onto (`onto`) and a projection onto the
/// image of C otherwise; every nonzero singular value of C is at least 1 (the status rule of
/// general::detail::apply_general_status_rule relies on it).
template <groups::LieGroup G>
void expect_the_auxiliary_map(std::mt19937& rng, bool onto) {
  constexpr int m = G::kDim;
  for (int trial = 0; trial < 4; ++trial) {
    const groups::TangentOf<G> v = random_tangent<G>(rng);
    const groups::CovectorOf<G> mu = random_tangent<G>(rng);
    // Sums of a few products of entries of size <= 1 with structure constants of size 1.
    EXPECT_NEAR_MATRIX(general::aux_to_xi<G>(v * mu.transpose()), groups::coad<G>(v, mu), 1e-14) << G::name();
    const groups::CovectorOf<G> xi = random_tangent<G>(rng);
    const groups::CovectorOf<G> round_trip = general::aux_to_xi<G>(general::xi_to_aux<G>(xi));
    if (onto) EXPECT_NEAR_MATRIX(round_trip, xi, 1e-14) << G::name();
    // Always a projection onto the image: applying it twice changes nothing.
    EXPECT_NEAR_MATRIX(general::aux_to_xi<G>(general::xi_to_aux<G>(round_trip)), round_trip, 1e-14) << G::name();
  }
  const Eigen::Matrix<double, m, m * m> c = general::aux_to_xi_matrix<G>();
  const Eigen::Matrix<double, m * m, m> c_plus = general::aux_pseudo_inverse<G>().matrix;
  EXPECT_NEAR_MATRIX(c * c_plus * c, c, 1e-14) << G::name();  // Moore–Penrose
  EXPECT_NEAR_MATRIX(c_plus * c * c_plus, c_plus, 1e-14) << G::name();
  EXPECT_GE(general::aux_pseudo_inverse<G>().smallest_singular_value, 1 - 1e-12) << G::name();
}

TEST(LieKernel, TheAuxiliaryMapTakesVMuToTheCoadjointAction) {
  std::mt19937 rng(kSeed + 30);
  expect_the_auxiliary_map<groups::SO3>(rng, true);
  expect_the_auxiliary_map<groups::SE2>(rng, true);
  expect_the_auxiliary_map<groups::SE3>(rng, true);
  // H3: [e1, e2] = e3 spans the centre, so C misses xi_3 (design §2.1, item 3): rank 2.
  expect_the_auxiliary_map<groups::Heisenberg>(rng, false);
  const Eigen::Vector3d centre_only(0, 0, 1);
  EXPECT_NEAR_MATRIX(general::xi_to_aux<groups::Heisenberg>(centre_only), Eigen::Matrix3d::Zero(), 1e-15);
}

// The Hessian structure a Lagrangian declares reaches the Lie-group kernel's scheme through every
// adapter and erasure (a KineticPotential reports it; OnGroupManifold, general::ErasedLagrangian,
// LieLagrangian and mechanics::ErasedLagrangian forward it), so that the particle on a
// Cartan-Schouten GroupManifold costs what the model does (bench_general,
// BM_Solve_CartanSchoutenModelOrManifold); before, every erased Lagrangian reported none.
TEST(LieKernel, TheHessianStructureTravelsThroughTheErasures) {
  using Structure = mechanics::RuntimeHessianStructure;
  const auto expect = [](const Structure& s, bool constant, bool independent, bool zero, const char* what) {
    EXPECT_EQ(s.constant_momentum_hessian, constant) << what;
    EXPECT_EQ(s.gradient_independent_of_velocity, independent) << what;
    EXPECT_EQ(s.zero_group_gradient, zero) << what;
  };
  const SO3Manifold so3 = SO3Manifold::cartan_schouten(0.3);
  const general::KineticPotential<SO3Manifold> free(paper_inertia());
  const auto potential = [](const groups::SO3::Element& g) { return g.trace(); };
  const auto gradient = [](const groups::SO3::Element&) { return Eigen::Vector3d::Zero().eval(); };
  const general::KineticPotential<SO3Manifold> pulled(paper_inertia(), potential, gradient);
  expect(mechanics::hessian_structure_of(free), true, true, true, "KineticPotential");
  expect(mechanics::hessian_structure_of(pulled), true, true, false, "KineticPotential with V");
  const ErasedLagrangian<SO3Manifold> erased_free(free), erased_model(general::OnGroupManifold<groups::SO3, mechanics::SO3Oscillator>{
                                                               mechanics::SO3Oscillator(paper_inertia())});
  expect(erased_free.hessian_structure(), true, true, true, "general::ErasedLagrangian(KineticPotential)");
  expect(erased_model.hessian_structure(), true, true, false, "general::ErasedLagrangian(OnGroupManifold(SO3Oscillator))");
  const mechanics::ErasedLagrangian<groups::SO3> lie(general::LieLagrangian<groups::SO3, ErasedLagrangian<SO3Manifold>>{erased_free, so3});
  expect(lie.hessian_structure(), true, true, true, "mechanics::ErasedLagrangian(LieLagrangian)");
  expect(mechanics::ErasedLagrangian<groups::SO3>(mechanics::RigidBody(paper_inertia())).hessian_structure(), true, true, true,
         "mechanics::ErasedLagrangian(RigidBody)");
}

// Both erased Lagrangians are one template (mechanics/erased.hpp) in each kernel's words, never the
// other's, so that what detects a member (the concepts, lagrangian_hessian, check_lagrangian's
// has_hessian) reads each as before.
template <class L, class... A>
concept HessianTakes = requires(const L& l, const A&... a) { l.hessian(a...); };
template <class L>
concept ReportsOwnHessian = requires(const L& l) { { l.has_hessian() } -> std::same_as<bool>; };
using ErasedOnSO3 = mechanics::ErasedLagrangian<groups::SO3>;
using SO3Element = groups::ElementOf<groups::SO3>;
using SO3Tangent = groups::TangentOf<groups::SO3>;
static_assert(std::is_same_v<ErasedOnSO3, mechanics::Erased<mechanics::ReducedTerms<groups::SO3>>> &&
              std::is_same_v<ErasedLagrangian<SO3Manifold>, mechanics::Erased<general::ManifoldTerms<SO3Manifold>>>);
static_assert(mechanics::ReducedLagrangian<ErasedOnSO3, groups::SO3> && !general::ManifoldLagrangian<ErasedOnSO3, SO3Manifold>);
static_assert(general::ManifoldLagrangian<ErasedLagrangian<SO3Manifold>, SO3Manifold> &&
              !mechanics::ReducedLagrangian<ErasedLagrangian<SO3Manifold>, groups::SO3>);
static_assert(HessianTakes<ErasedOnSO3, double, SO3Element, SO3Tangent> &&
              !HessianTakes<ErasedOnSO3, groups::SO3, double, SO3Element, SO3Tangent>);
static_assert(HessianTakes<ErasedLagrangian<SO3Manifold>, SO3Manifold, double, SO3Element, SO3Tangent> &&
              !HessianTakes<ErasedLagrangian<SO3Manifold>, double, SO3Element, SO3Tangent>);
static_assert(ReportsOwnHessian<ErasedLagrangian<SO3Manifold>> && !ReportsOwnHessian<ErasedOnSO3>);

// Design §5.4, item 1: the dispatched solve against the general kernel, node by node.
TEST(LieKernel, GeneralSolveOnCartanSchoutenRunsTheLieKernel) {
  for_every_case([](const auto& p, SchemeOrder order, const std::string& name) {
    const auto lie = general::solve(p, shooting_options(order));
    const auto reference = general::solve_general_shooting(p, {.order = order, .tolerance = kTol});
    ASSERT_TRUE(lie.converged()) << name << ": " << lie.message;
    ASSERT_TRUE(reference.converged()) << name << ": " << reference.message;
    EXPECT_TRUE(has(lie.message, "Lie-group kernel")) << name << ": " << lie.message;
    EXPECT_TRUE(has(reference.message, "constant frame components")) << name << ": " << reference.message;
    EXPECT_EQ(lie.method, Method::Shooting) << name;
    EXPECT_EQ(lie.order, static_cast<int>(order)) << name;
    EXPECT_EQ(lie.branch, "direct from the geodesic guess") << name;
    EXPECT_LE(lie.terminal_error, kTol) << name;
    EXPECT_LE(lie.xi_terminal, kTol * std::max(1.0, general::xi_scale(p))) << name;
    EXPECT_NEAR_MATRIX(lie.v0, reference.v0, 1e-9) << name;
    EXPECT_NEAR_MATRIX(lie.Xi0, reference.Xi0, 1e-9) << name;
    EXPECT_NEAR_MATRIX(lie.trajectory.frame.front(), p.initial_frame(), 0.0) << name;  // Ad(e) = I = frame0
    expect_same_nodes(lie.trajectory, reference.trajectory, 1e-9, name);
  });
}

// Design §5.4, item 2, independent of where Levenberg–Marquardt stops: the general scheme swept
// from the rebuilt (v0, Xi0) is the rebuilt trajectory, frame and Xi included.
TEST(LieKernel, TheRebuiltTrajectoryIsASweepOfTheGeneralScheme) {
  for_every_case([](const auto& p, SchemeOrder order, const std::string& name) {
    using M = std::decay_t<decltype(p.manifold)>;
    const auto s = general::solve(p, shooting_options(order));
    ASSERT_TRUE(s.converged()) << name << ": " << s.message;
    const general::GeneralScheme<M, ErasedLagrangian<M>> scheme(p, order);
    GeneralTrajectory<M> swept;
    std::string failure;
    ASSERT_TRUE(general::general_sweep(scheme, s.v0, s.Xi0, failure, &swept).has_value()) << name << ": " << failure;
    ASSERT_EQ(swept.t.size(), s.trajectory.t.size()) << name;
    EXPECT_LE(relative_gap(swept.q, s.trajectory.q), 1e-11) << name << ": q";
    EXPECT_LE(relative_gap(swept.frame, s.trajectory.frame), 1e-11) << name << ": frame";
    EXPECT_LE(relative_gap(swept.v, s.trajectory.v), 1e-11) << name << ": v";
    EXPECT_LE(relative_gap(swept.mu, s.trajectory.mu), 1e-11) << name << ": mu";
    EXPECT_LE(relative_gap(swept.Xi, s.trajectory.Xi), 1e-11) << name << ": Xi";
  });
  // C(Xi_k) is the Lie-group solver's xi_k: the typed RigidBody solve (compiled in the library)
  // against the dispatched erased one, both at |r| <= 1e-12 (1e-9, as above).
  for (const SchemeOrder order : kOrders) {
    const auto lie_problem = paper_free_body(0.3, 200, 5);
    const auto reference = transported::solve(lie_problem, shooting_options(order));
    const auto s = general::solve(on_cartan_schouten(lie_problem), shooting_options(order));
    ASSERT_TRUE(reference.converged() && s.converged()) << reference.message << " / " << s.message;
    ASSERT_EQ(reference.trajectory.xi.size(), s.trajectory.Xi.size());
    double worst = 0;
    for (std::size_t k = 0; k < s.trajectory.Xi.size(); ++k) {
      worst = std::max(worst, max_abs_diff(general::aux_to_xi<groups::SO3>(s.trajectory.Xi[k]), reference.trajectory.xi[k]));
    }
    EXPECT_LE(worst, 1e-9) << "order " << static_cast<int>(order);
  }
}

// Design §5.4, item 3: verify_general passes the Lie kernel's result with the general kernel's figures.
TEST(LieKernel, VerifyGeneralPassesTheLieKernelResult) {
  for_every_case([](const auto& p, SchemeOrder order, const std::string& name) {
    const auto lie = general::solve(p, shooting_options(order));
    const auto reference = general::solve_general_shooting(p, {.order = order, .tolerance = kTol});
    ASSERT_TRUE(lie.converged() && reference.converged()) << name << ": " << lie.message << " / " << reference.message;
    const verify::Report report = general::verify_general(p, lie.trajectory, lie.order, kTol, lie.status);
    const verify::Report expected = general::verify_general(p, reference.trajectory, reference.order, kTol, reference.status);
    EXPECT_TRUE(report.passed()) << name << "\n" << report.text();
    ASSERT_EQ(report.checks.size(), expected.checks.size()) << name;
    for (std::size_t i = 0; i < report.checks.size(); ++i) {
      const verify::Check& c = report.checks[i];
      const verify::Check& e = expected.checks[i];
      ASSERT_EQ(c.name, e.name);
      if (c.name == "boundary") {
        EXPECT_LE(c.figure, kTol) << name;
      } else {
        EXPECT_LE(c.figure, 2 * e.figure + 1e-12) << name << ": " << c.name;
        EXPECT_LE(e.figure, 2 * c.figure + 1e-12) << name << ": " << c.name;
      }
    }
  });
}

// Design §5.4, item 4: guesses, continuation in T, the time limit and collocation.
TEST(LieKernel, GuessesAndOptionsMapOntoTheLieKernel) {
  const auto p = on_cartan_schouten(paper_free_body(0.3, 200, 5));
  const auto options = shooting_options(SchemeOrder::First);
  const auto s = general::solve(p, options);
  ASSERT_TRUE(s.converged()) << s.message;

  // A symmetric Xi is in the kernel of C on so(3) (C(Xi)_i = sum eps_kin Xi(k, n)): a guess Xi0 + K
  // is the guess Xi0 to the Lie kernel, and the rebuilt Xi0 carries no trace of K.
  std::mt19937 rng(kSeed + 31);
  const Eigen::Matrix3d a = random_vector<Eigen::Matrix<double, 9, 1>>(rng, 1.0).reshaped(3, 3);
  const Eigen::Matrix3d kernel = a + a.transpose();
  EXPECT_NEAR_MATRIX(general::aux_to_xi<groups::SO3>(kernel), Eigen::Vector3d::Zero(), 1e-15);
  const auto perturbed = general::solve(p, options, GeneralGuess<SO3Manifold>{Eigen::Vector3d(0.9 * s.v0), Eigen::Matrix3d(s.Xi0 + kernel), std::nullopt});
  ASSERT_TRUE(perturbed.converged()) << perturbed.message;
  EXPECT_EQ(perturbed.branch, "direct from the given guess");
  EXPECT_NEAR_MATRIX(perturbed.v0, s.v0, 1e-9);
  EXPECT_NEAR_MATRIX(perturbed.Xi0, s.Xi0, 1e-9);
  expect_same_nodes(perturbed.trajectory, s.trajectory, 1e-9, "from v0 and Xi0 + K");

  // A trajectory guess (the solution itself) starts at the root: at most one iteration.
  GeneralGuess<SO3Manifold> start;
  start.trajectory = s.trajectory;
  const auto again = general::solve(p, options, start);
  ASSERT_TRUE(again.converged()) << again.message;
  EXPECT_EQ(again.branch, "direct from the given guess");
  EXPECT_LE(again.inner_iterations, 1);
  EXPECT_NEAR_MATRIX(again.v0, s.v0, 1e-9);

  // The default strategy starts with the same shooting.
  cartan::SolveOptions automatic;
  automatic.tol = kTol;
  const auto by_default = general::solve(p, automatic);
  ASSERT_TRUE(by_default.converged()) << by_default.message;
  EXPECT_TRUE(has(by_default.message, "Lie-group kernel")) << by_default.message;
  EXPECT_EQ(by_default.branch, "shooting (direct from the geodesic guess)");  // the default strategy's words

  // The oscillator at T = 12 (docs/paper-notes.md#erratum-4): direct shooting from the geodesic
  // guess fails at lambda = 1/2 (tests/cli/test_cli.py, the same Lie-group shooting), continuation
  // in T reaches it from T = 3.
  auto long_horizon = shooting_options(SchemeOrder::First, 1e-8);
  long_horizon.continuation = cartan::Continuation::T;
  const auto continued = general::solve(on_cartan_schouten(paper_oscillator(0.5)), long_horizon);
  ASSERT_TRUE(continued.converged()) << continued.message;
  EXPECT_EQ(continued.branch.rfind("continued in T from", 0), 0u)
      << continued.branch << " (the T = 12 oscillator no longer needs continuation: pick a harder case)";
  EXPECT_TRUE(has(continued.message, "Lie-group kernel")) << continued.message;
  EXPECT_LE(continued.terminal_error, 1e-8);
  EXPECT_EQ(continued.trajectory.t.size(), 801u);
  EXPECT_EQ(continued.trajectory.frame.size(), 801u);
  EXPECT_EQ(continued.trajectory.Xi.size(), 801u);

  // A time limit far below one sweep (N = 1e5): status time-limit; whatever trajectory the stop
  // left is converted whole (none, or one with a frame and Xi at every node).
  auto hurried = options;
  hurried.time_limit = 1e-3;
  const auto stopped = general::solve(on_cartan_schouten(paper_free_body(0.3, 100000, 5)), hurried);
  EXPECT_EQ(stopped.status, Status::TimeLimit) << stopped.message;
  EXPECT_TRUE(has(stopped.message, "Lie-group kernel")) << stopped.message;
  EXPECT_EQ(stopped.trajectory.frame.size(), stopped.trajectory.t.size());
  EXPECT_EQ(stopped.trajectory.Xi.size(), stopped.trajectory.t.size());

  // Collocation stays the general one (GeneralCollocation.CartanSchoutenReproducesTheLieGroupCollocation
  // checks its values).
  cartan::SolveOptions collocation;
  collocation.method = Method::Collocation;
  collocation.tol = 1e-6;
  const auto collocated = general::solve(on_cartan_schouten(paper_free_body(0.3, 50, 5)), collocation);
  EXPECT_EQ(collocated.method, Method::Collocation);
  EXPECT_EQ(collocated.order, kCollocationOrder);
  EXPECT_FALSE(has(collocated.message, "Lie-group kernel")) << collocated.message;
}

// The Lie-group kernel's own methods through general::solve (solve.hpp, header comment): multiple
// shooting, two-level and shooting continued in lambda run as transported::solve runs them on the
// paper's problem, so the nodes are the Lie-group solve's by the same method (both stop at tol 1e-10
// on the same discrete equations, 1e-8 at the nodes; the two-level scheme stops on the change of xi,
// 1e-7), with the frame rebuilt as the transport P_k = Ad(h_k) and Xi_N = C^+ xi_N. Anywhere else
// (another connection, a frame0 other than the identity, the sphere) they are refused by name, and
// the variational method everywhere.
TEST(LieKernel, TheLieGroupMethodsAreTheKernelsCapabilities) {
  const auto lie_problem = paper_oscillator(0.3, 100, 3);
  const auto p = on_cartan_schouten(lie_problem);
  struct Case {
    Method method;
    cartan::Continuation continuation;
    double tolerance;
  };
  for (const Case c : {Case{Method::MultipleShooting, cartan::Continuation::None, 1e-8},
                       Case{Method::TwoLevel, cartan::Continuation::None, 1e-7},
                       Case{Method::Shooting, cartan::Continuation::Lambda, 1e-8}}) {
    cartan::SolveOptions options;
    options.method = c.method;
    options.continuation = c.continuation;
    const std::string name = std::string(to_string(c.method)) + " " + std::string(to_string(c.continuation));
    const auto reference = transported::solve(lie_problem, options);
    const auto s = general::solve(p, options);
    ASSERT_TRUE(reference.converged()) << name << ": " << reference.message;
    ASSERT_TRUE(s.converged()) << name << ": " << s.message;
    EXPECT_EQ(s.method, reference.method) << name;
    EXPECT_TRUE(has(s.message, "Lie-group kernel")) << name << ": " << s.message;
    EXPECT_LE(max_gap(s.trajectory.q, reference.trajectory.g), c.tolerance) << name;
    EXPECT_LE(max_gap(s.trajectory.mu, reference.trajectory.mu), c.tolerance) << name;
    EXPECT_LE(s.terminal_error, 1e-9) << name;
    // The rebuilt frame and Xi: Ad of the transport, and Xi_N = C^+ xi_N.
    ASSERT_EQ(s.trajectory.frame.size(), s.trajectory.t.size()) << name;
    ASSERT_EQ(s.trajectory.Xi.size(), s.trajectory.t.size()) << name;
    const auto P = transported::along_transport<groups::SO3>(lie_problem.lambda, reference.trajectory).P;
    EXPECT_LE(max_gap(s.trajectory.frame, P), c.tolerance) << name;
    EXPECT_NEAR_MATRIX(general::aux_to_xi<groups::SO3>(s.trajectory.Xi.back()), reference.trajectory.xi.back(),
                       c.tolerance) << name;
  }
  // A guess trajectory enters as the Lie-group solver's (xi = C(Xi)): from the solution itself,
  // multiple shooting stops at once.
  cartan::SolveOptions multiple;
  multiple.method = Method::MultipleShooting;
  const auto first = general::solve(p, multiple);
  ASSERT_TRUE(first.converged()) << first.message;
  GeneralGuess<SO3Manifold> start;
  start.trajectory = first.trajectory;
  const auto again = general::solve(p, multiple, start);
  ASSERT_TRUE(again.converged()) << again.message;
  EXPECT_LE(again.inner_iterations, 1);

  // Refused by name where the kernel does not apply, and continuation in lambda with collocation.
  auto levi_civita = p;
  levi_civita.manifold = SO3Manifold::levi_civita(Eigen::Matrix3d::Identity());
  expect_invalid([&] { (void)general::solve(levi_civita, multiple); },
                 {"multiple-shooting", "not available for a general connection"});
  auto rotated = p;
  rotated.frame0 = groups::SO3::exp(Eigen::Vector3d(0.1, 0.2, 0.3));
  cartan::SolveOptions in_lambda;
  in_lambda.method = Method::Shooting;
  in_lambda.continuation = cartan::Continuation::Lambda;
  expect_invalid([&] { (void)general::solve(rotated, in_lambda); }, {"continuation = lambda", "identity frame0"});
  cartan::SolveOptions collocation_in_lambda;
  collocation_in_lambda.method = Method::Collocation;
  collocation_in_lambda.continuation = cartan::Continuation::Lambda;
  expect_invalid([&] { (void)general::solve(p, collocation_in_lambda); }, {"continuation = lambda", "collocation"});
  cartan::SolveOptions variational;
  variational.method = Method::Variational;
  expect_invalid([&] { (void)general::solve(p, variational); }, {"variational", "the Lie-group solve only"});
}

// The default strategy is one (solvers/strategy.hpp): on the Lie-group kernel it has the kernel's
// capabilities and window, so where shooting and continuation in T fail (the oscillator at
// lambda = 2, T = 3: tests/golden auto_oscillator_lambda_2_T3) general::solve takes the path
// transported::solve takes, continuation in lambda from 0, and lands on the same solution (1e-8 at
// the nodes: both stop within tol = 1e-10 of the same discrete root, as the methods above).
TEST(LieKernel, TheDefaultStrategyHasTheKernelsCapabilities) {
  const auto lie_problem = paper_oscillator(2.0, 300, 3);
  cartan::SolveOptions automatic;
  const auto reference = transported::solve(lie_problem, automatic);
  const auto s = general::solve(on_cartan_schouten(lie_problem), automatic);
  ASSERT_TRUE(reference.converged()) << reference.message;
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_TRUE(reference.branch.starts_with("continuation in lambda from 0")) << reference.branch;
  EXPECT_EQ(s.branch, reference.branch);
  EXPECT_TRUE(has(s.message, "Lie-group kernel")) << s.message;
  EXPECT_LE(max_gap(s.trajectory.q, reference.trajectory.g), 1e-8);
  EXPECT_LE(max_gap(s.trajectory.mu, reference.trajectory.mu), 1e-8);
}

// Design §5.4, item 5: the general kernel everywhere else: another connection, Cartan–Schouten
// given by its coefficients (no lambda), and a frame0 other than the identity.
TEST(LieKernel, OtherConnectionsKeepTheGeneralKernel) {
  const auto lie_problem = paper_free_body(0.3, 50, 5);
  const auto options = shooting_options(SchemeOrder::First, 1e-10);
  const auto kernel_of = [&](const SO3Manifold& manifold, std::optional<Eigen::Matrix3d> frame0) {
    auto p = on_cartan_schouten(lie_problem);
    p.manifold = manifold;
    p.frame0 = frame0;
    return general::solve(p, options).message;
  };
  const std::string levi_civita = kernel_of(SO3Manifold::levi_civita(Eigen::Matrix3d::Identity()), std::nullopt);
  EXPECT_TRUE(has(levi_civita, "general shooting")) << levi_civita;
  EXPECT_FALSE(has(levi_civita, "Lie-group kernel")) << levi_civita;
  const std::string by_coefficients =
      kernel_of(SO3Manifold(connections::cartan_schouten<groups::SO3>(0.3)), std::nullopt);
  EXPECT_TRUE(has(by_coefficients, "general shooting")) << by_coefficients;
  EXPECT_TRUE(has(by_coefficients, "constant frame components")) << by_coefficients;
  const std::string rotated = kernel_of(SO3Manifold::cartan_schouten(0.3), groups::SO3::exp(Eigen::Vector3d(0.1, 0.2, 0.3)));
  EXPECT_TRUE(has(rotated, "general shooting")) << rotated;
  const std::string identity = kernel_of(SO3Manifold::cartan_schouten(0.3), Eigen::Matrix3d::Identity());
  EXPECT_TRUE(has(identity, "Lie-group kernel")) << identity;
}

}  // namespace cartan::testing::lie_kernel_tests
