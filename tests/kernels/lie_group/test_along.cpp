// Quantities along a solution (kernels/lie_group/along.hpp) against the scheme that made it: the
// transport rebuilt from the nodes alone equals the scheme's own transport element h_k (both
// orders: each step moves g and h with the same velocity, disc-grp and disc-exp), u_k = P_k v_k is
// the scheme's rate u at the node, the energy is lagrangian_energy, and the cumulative action ends
// on transported_action bit for bit.
#include <cmath>
#include <limits>
#include <random>

#include "cartan/kernels/lie_group/along.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "test_support.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace cartan::testing {
namespace {

/// Runs N steps of the scheme from a random (v0, xi0) (scale 0.5: steps well inside the
/// injectivity radius of exp, so that log(g_k^-1 g_k+1) is the step's h u) and compares.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void expect_along_matches_the_scheme(const transported::TransportedProblem<G, L>& problem, transported::SchemeOrder order,
                                     std::mt19937& rng) {
  const transported::TransportedScheme<G, L> scheme(problem, order);
  auto node = scheme.initial(random_vector<groups::TangentOf<G>>(rng, 0.5), random_vector<groups::CovectorOf<G>>(rng, 0.5));
  transported::TransportedTrajectory<G> x;
  std::vector<groups::ElementOf<G>> transport;
  std::vector<groups::TangentOf<G>> rate_u;
  for (int k = 0;; ++k) {
    x.push(node);
    transport.push_back(node.transport);
    rate_u.push_back(scheme.rates(node).u);
    if (k == problem.N) break;
    transported::SchemeNode<G> next;
    scheme.step(node, next);
    node = next;
  }
  const transported::AlongSolution<G> along = transported::along_solution<G>(problem.lagrangian, problem.lambda, x);
  ASSERT_EQ(along.P.size(), x.g.size());
  EXPECT_EQ(along.P.front(), groups::AlgebraMatrixOf<G>::Identity());
  for (std::size_t k = 0; k < x.g.size(); ++k) {
    // Rounding of one exp-log round trip per step, accumulated over N = 40 steps: 1e-12.
    EXPECT_LE((along.P[k] - G::Ad(transport[k])).cwiseAbs().maxCoeff(), 1e-12)
        << G::name() << " lambda " << problem.lambda << " order " << static_cast<int>(order) << " node " << k;
    EXPECT_LE((along.u[k] - rate_u[k]).norm(), 1e-12 * (1 + rate_u[k].norm())) << G::name() << " node " << k;
    EXPECT_EQ(along.energy[k], mechanics::lagrangian_energy<G>(problem.lagrangian, x.t[k], x.g[k], x.v[k]));
  }
  EXPECT_EQ(along.action.front(), 0.0);
  EXPECT_EQ(along.action.back(), transported::transported_action<G>(problem.lagrangian, problem.lambda, x.t, x.g));
}

TEST(AlongSolution, RebuildsTheSchemesTransportAndRates) {
  std::mt19937 rng(kSeed);
  for (double lambda : {0.0, 0.3, 1.0, 1.4}) {
    for (transported::SchemeOrder order : {transported::SchemeOrder::First, transported::SchemeOrder::Second}) {
      expect_along_matches_the_scheme(paper_oscillator(lambda, 40, 2.0), order, rng);
      const transported::TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator> h3{
          mechanics::h3_oscillator(), lambda, 1.0, 40, groups::Heisenberg::Element(0.2, -0.1, 0.3),
          groups::Heisenberg::Element(1.0, 0.5, 0.8)};
      expect_along_matches_the_scheme(h3, order, rng);
      const Eigen::Matrix<double, 6, 1> inertia = (Eigen::Matrix<double, 6, 1>() << 1, 1, 1, 2, 3, 4).finished();
      const transported::TransportedProblem<groups::SE3, mechanics::SE3FreeBody> se3{
          mechanics::SE3FreeBody(inertia.asDiagonal().toDenseMatrix()), lambda, 1.0, 40, groups::SE3::identity(),
          groups::SE3::identity()};
      expect_along_matches_the_scheme(se3, order, rng);
    }
  }
}

TEST(AlongSolution, EmptyWithoutAnIterateAndNaNForNonFiniteSamples) {
  const auto problem = paper_free_body(0.5, 4, 1.0);
  transported::TransportedTrajectory<groups::SO3> x;
  EXPECT_TRUE(transported::along_solution<groups::SO3>(problem.lagrangian, 0.5, x).P.empty());
  const transported::TransportedScheme<groups::SO3, mechanics::RigidBody> scheme(problem, transported::SchemeOrder::First);
  x.push(scheme.initial(Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d::Zero()));
  auto bad = scheme.initial(Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d::Zero());
  bad.v[1] = std::numeric_limits<double>::quiet_NaN();
  bad.t = 0.5;
  x.push(bad);
  const auto along = transported::along_solution<groups::SO3>(problem.lagrangian, 0.5, x);
  ASSERT_EQ(along.energy.size(), 2u);
  EXPECT_TRUE(std::isnan(along.energy[0]) && std::isnan(along.action[1]) && std::isnan(along.P[0](0, 0)));
  x.mu.pop_back();
  EXPECT_THROW(transported::along_solution<groups::SO3>(problem.lagrangian, 0.5, x), std::invalid_argument);
}

}  // namespace
}  // namespace cartan::testing
