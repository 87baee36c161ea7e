// eq:reduced-system on any group by collocation (kernels/lie_group/collocation_system.hpp): on H3 it
// agrees with the closed-form system, and on SO(3) (free rigid body, oscillator) it reaches the
// continuous solution the transported shooting solvers approximate.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cartan/kernels/lie_group/collocation_system.hpp"
#include "cartan/kernels/lie_group/heisenberg_collocation.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/methods/lie_group/continuation.hpp"
#include "test_support.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace cartan::transported {
namespace {

using Eigen::VectorXd;

// H3 with g, the transport element h and xi as states must reproduce the closed-form transport
// (para-trans-Heis) of heisenberg_collocation.hpp, with xi integrated along its solution: both
// solve the same BVP to tol 1e-10, whose
// errors (O(h^4), far below the residual) are ~1e-12; 1e-9 leaves room for the two meshes.
TEST(TransportedCollocation, HeisenbergAgreesWithTheClosedFormSystem) {
  using Generic = TransportedCollocation<groups::Heisenberg, mechanics::HeisenbergQuadraticPotential>;
  for (double lambda : {0.0, 0.5, 1.0}) {
    const TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator> p{mechanics::h3_oscillator(), lambda, 1.0, 10,
                                                         Eigen::Vector3d(0.3, -0.2, 0.5), Eigen::Vector3d(1, 0.5, 0.8)};
    const numerics::CollocationOptions options{.tol = 1e-10, .max_nodes = 5000};
    const numerics::BvpResult generic = Generic::solve(p, options);
    const numerics::BvpResult closed = solve_heisenberg_collocation(p, options);
    ASSERT_TRUE(generic.success()) << generic.message;
    ASSERT_TRUE(closed.success()) << closed.message;
    const VectorXd times = VectorXd::LinSpaced(21, 0, 1);
    const Eigen::MatrixXd xi = heisenberg_xi(p, closed, times);  // quadrature vs xi as a state
    for (Eigen::Index j = 0; j < times.size(); ++j) {
      const VectorXd a = generic(times[j]), b = closed(times[j]);
      EXPECT_LE((a.segment<3>(Generic::kG) - b.head<3>()).cwiseAbs().maxCoeff(), 1e-9) << times[j];
      EXPECT_LE((a.segment<3>(Generic::kV) - b.segment<3>(3)).cwiseAbs().maxCoeff(), 1e-9) << times[j];
      EXPECT_LE((a.segment<3>(Generic::kXi) - xi.col(j)).cwiseAbs().maxCoeff(), 1e-9) << times[j];
    }
  }
}

// guess_from rebuilds the transport element along a discrete path: along the geodesic
// g(t) = g0 exp(t u) it must give h(t) = exp(-lambda t u) and reproduce geodesic_guess (the
// products of exact exponentials of one direction differ only by rounding, ~1e-15 per step).
TEST(TransportedCollocation, GuessFromATrajectoryRebuildsTheTransport) {
  using Collocation = TransportedCollocation<groups::SO3, mechanics::ZeroPotential<groups::SO3>>;
  const auto problem = testing::paper_free_body(0.3, 40, 5.0);
  VectorXd t_geodesic, t;
  Eigen::MatrixXd y_geodesic, y;
  Collocation::geodesic_guess(problem, t_geodesic, y_geodesic);
  TransportedTrajectory<groups::SO3> path;
  for (Eigen::Index i = 0; i < t_geodesic.size(); ++i) {
    SchemeNode<groups::SO3> node;
    node.t = t_geodesic[i];
    node.g = Collocation::element(y_geodesic.col(i), Collocation::kG);
    node.v = y_geodesic.col(i).segment<3>(Collocation::kV);
    node.xi.setZero();
    node.mu.setZero();
    node.transport = groups::SO3::identity();
    path.push(node);
  }
  Collocation::guess_from(problem, path, t, y);
  EXPECT_EQ(t, t_geodesic);
  EXPECT_LE((y - y_geodesic).cwiseAbs().maxCoeff(), 1e-13);
  path.t.resize(1);
  testing::expect_invalid([&] { Collocation::guess_from(problem, path, t, y); }, "trajectory.t.size() = 1");
}

/// Max over the shooting solution's nodes of the difference to the collocation solution in
/// g (matrix entries), v and xi.
template <class Collocation>
double difference(const numerics::BvpResult& c, const TransportedSolution<groups::SO3>& s) {
  double worst = 0;
  for (std::size_t k = 0; k < s.trajectory.t.size(); ++k) {
    const VectorXd y = c(s.trajectory.t[k]);
    worst = std::max({worst, (Collocation::element(y, Collocation::kG) - s.trajectory.g[k]).cwiseAbs().maxCoeff(),
                      (y.template segment<3>(Collocation::kV) - s.trajectory.v[k]).cwiseAbs().maxCoeff(),
                      (y.template segment<3>(Collocation::kXi) - s.trajectory.xi[k]).cwiseAbs().maxCoeff()});
  }
  return worst;
}

// SO(3), the paper's free body (T = 5) and oscillator (T = 3) with the paper's endpoints: the
// collocation solution (tol 1e-10, error ~1e-12) and the order-2 shooting solutions (continued
// in T where needed) approximate the same continuous solution, so their difference shrinks at
// the scheme's order 2 (within 0.25). g and h stay orthogonal to the collocation accuracy.
template <class Problem>
void expect_same_continuous_solution(const std::function<Problem(int)>& make, const std::string& name) {
  using Collocation = TransportedCollocation<groups::SO3, std::remove_cvref_t<decltype(make(1).lagrangian.potential())>>;
  const numerics::BvpResult c = Collocation::solve(make(20), {.tol = 1e-10, .max_nodes = 20000});
  ASSERT_TRUE(c.success()) << name << ": " << c.message;
  EXPECT_LE(Collocation::orthogonality_defect(c), 1e-9) << name;
  std::vector<double> d;
  for (int N : {50, 100, 200}) {
    const auto s = solve_continuation_in_T(make(N), {.shooting = {.order = SchemeOrder::Second, .tolerance = 1e-13}});
    ASSERT_TRUE(s.converged()) << name << ": " << s.message;
    d.push_back(difference<Collocation>(c, s));
    ::testing::Test::RecordProperty(name + "_N" + std::to_string(N), format_value(d.back()));
  }
  for (std::size_t j = 0; j + 1 < d.size(); ++j) {
    EXPECT_NEAR(std::log2(d[j] / d[j + 1]), 2.0, 0.25) << name << ": " << d[j] << " -> " << d[j + 1];
  }
}

TEST(TransportedCollocation, SO3FreeBodyMatchesShootingAtTheSchemesOrder) {
  for (double lambda : {0.0, 0.5, 1.0}) {
    expect_same_continuous_solution<TransportedProblem<groups::SO3, mechanics::RigidBody>>(
        [lambda](int N) { return testing::paper_free_body(lambda, N, 5.0); }, "free_body_lambda" + format_value(lambda));
  }
}

TEST(TransportedCollocation, SO3OscillatorMatchesShootingAtTheSchemesOrder) {
  for (double lambda : {0.0, 0.5, 1.0}) {
    expect_same_continuous_solution<TransportedProblem<groups::SO3, mechanics::SO3Oscillator>>(
        [lambda](int N) { return testing::paper_oscillator(lambda, N, 3.0); }, "oscillator_lambda" + format_value(lambda));
  }
}

}  // namespace
}  // namespace cartan::transported
