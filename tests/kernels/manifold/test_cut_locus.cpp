// Honesty at the cut locus (issue 29): on every manifold instance, endpoint pairs on the cut
// locus of the target (the antipode on S^2, a rotation by pi on SO(3) and SE(2); a far point where
// there is none) and next to it. A result that says converged, and a result the verifier passes,
// ends at qT by the storage distance (the embedding's, the matrices', the coordinates'), not only
// by the logarithm, which may be 0 or meaningless there; a trajectory that misses qT never passes.
// The solves and checks are the library's compiled ones (kernels/manifold/compiled.hpp: the erased
// Lagrangian on every shipped manifold).

#include <array>
#include <numbers>
#include <random>

#include "cartan/kernels/manifold/compiled.hpp"
#include "manifolds/manifold_instances.hpp"
#include "general_cases.hpp"

namespace cartan::testing {
namespace {

using namespace cartan::general;

template <class Instance>
class CutLocusTest : public ::testing::Test {
 protected:
  using M = typename Instance::Manifold;
  using Point = manifolds::PointOf<M>;
  static constexpr int m = M::kDim;

  /// A point on the cut locus of q where the instance has one, otherwise a point about 2.5 away.
  static Point cut_point(const M& manifold, const Point& q, std::mt19937& rng) {
    if constexpr (std::is_same_v<M, manifolds::Sphere>) {
      return -q;
    } else if constexpr (std::is_same_v<M, manifolds::GroupManifold<groups::SO3>>) {
      return manifold.step(q, Eigen::Vector3d(std::numbers::pi * random_vector<Eigen::Vector3d>(rng, 1.0).normalized()));
    } else if constexpr (std::is_same_v<M, manifolds::GroupManifold<groups::SE2>>) {
      return manifold.step(q, Eigen::Vector3d(0.7, -0.4, std::numbers::pi));  // (x, y, theta = pi)
    } else if constexpr (std::is_same_v<M, manifolds::Chart<2>>) {
      return q + Eigen::Vector2d(2.0, -0.5);  // stays in the half-plane y > 0 (q_y >= 1)
    } else {
      const manifolds::VectorOf<M> x = random_tangent_at(manifold, q, rng);
      return manifold.step(q, manifolds::VectorOf<M>(2.5 * x / x.norm()));
    }
  }

  /// A point 1e-7 from p (next to the cut locus when p is on it).
  static Point beside(const M& manifold, const Point& p, std::mt19937& rng) {
    const manifolds::VectorOf<M> x = random_tangent_at(manifold, p, rng);
    return manifold.step(p, manifolds::VectorOf<M>(1e-7 * x / x.norm()));
  }

  static ErasedProblem<M> problem(const M& manifold, const Point& q0, const Point& qT) {
    const Eigen::Matrix<double, m, m> a = Eigen::Matrix<double, m, m>::Identity() +
                                          Eigen::Matrix<double, m, 1>::LinSpaced(0.0, 1.5).asDiagonal().toDenseMatrix();
    // The anisotropic l depends on the frame: given, so that the problem is defined at antipodal
    // endpoints too (where default_frame falls back on tangent_basis(q0)).
    return {manifold, ErasedLagrangian<M>(KineticPotential<M>(a)), 1.0, 40, q0, qT, manifolds::default_frame(manifold, q0, qT)};
  }

  /// The storage distance a passing or converged result may have from qT: the solver's and the
  /// verifier's tolerance is on the length of the logarithm, which bounds the storage distance up
  /// to the embedding's Lipschitz constant on the points involved (1 on S^2, sqrt 2 for SO(3)
  /// matrices, cosh of the distance from the origin on H^2 and a factor 1 + |q| for the product
  /// of H3 and SE(2) coordinates; under 30 here): 100 (1 + |qT|) tol.
  static double allowed(const Point& qT, double tol) { return 100 * (1 + qT.norm()) * tol; }
};

TYPED_TEST_SUITE(CutLocusTest, AllManifolds);

// The separation is the length of the logarithm where it is one, and never 0 between distinct
// points: at the cut locus it is at least the storage distance.
TYPED_TEST(CutLocusTest, SeparationIsZeroOnlyAtTheTarget) {
  using Space = typename TestFixture::M;
  const Space manifold = TypeParam::make();
  std::mt19937 rng(kSeed + 29);
  for (int trial = 0; trial < 4; ++trial) {
    const auto q = TypeParam::point(manifold, rng);
    const auto far = TestFixture::cut_point(manifold, q, rng);
    const auto near = TestFixture::beside(manifold, far, rng);
    for (const auto& p : {far, near}) {
      EXPECT_GT(manifolds::separation(manifold, q, p), 0.1) << manifold.name();
      EXPECT_GT(manifolds::point_distance(manifold, q, p), 0.1) << manifold.name();
    }
    EXPECT_LE(manifolds::separation(manifold, q, q), 1e-15) << manifold.name();  // the rounding of one logarithm
    // A nearby point: a logarithm, whose length the separation is (rounding: 1e-12 relative).
    const auto x = random_tangent_at(manifold, q, rng, 0.1);
    const auto p = manifold.step(q, x);
    const auto d = manifolds::checked_difference(manifold, q, p);
    EXPECT_TRUE(d.reaches) << manifold.name();
    EXPECT_NEAR(manifolds::separation(manifold, q, p), (manifolds::dual_frame<Space>(manifold.tangent_basis(q)) * d.x).norm(),
                1e-12)
        << manifold.name();
  }
}

// The reported bug: a trajectory that stays at q0 (v = 0) checked against qT on the cut locus of
// q0. The logarithm on S^2 used to be 0 there and the boundary check passed it.
TYPED_TEST(CutLocusTest, ATrajectoryThatMissesTheTargetNeverPasses) {
  using Space = typename TestFixture::M;
  const Space manifold = TypeParam::make();
  std::mt19937 rng(kSeed + 30);
  const auto q0 = TypeParam::point(manifold, rng);
  for (const auto& qT : {TestFixture::cut_point(manifold, q0, rng), TestFixture::beside(manifold, q0, rng)}) {
    const auto p = TestFixture::problem(manifold, q0, qT);
    GeneralTrajectory<Space> still;
    for (int k = 0; k <= p.N; ++k) {
      still.push({p.step() * k, q0, p.initial_frame(), manifolds::ComponentsOf<Space>::Zero(),
                  manifolds::ComponentMatrixOf<Space>::Zero(), manifolds::ComponentsOf<Space>::Zero()});
    }
    const verify::Report report = verify_general(p, still, 1, 1e-10);
    ASSERT_EQ(report.checks.front().name, "boundary");
    EXPECT_FALSE(report.checks.front().passed()) << manifold.name() << "\n" << report.text();
    EXPECT_FALSE(report.passed());
  }
}

// Shooting from the geodesic guess and from v0 = 0 (whose q_N = q0 is on the cut locus of qT), at
// both orders, onto and next to the cut locus (and to a point 0.2 away, which converges): converged
// results end at qT, and so do results the verifier passes; the others are failures with their status.
TYPED_TEST(CutLocusTest, ConvergedAndPassingResultsEndAtTheTarget) {
  using Space = typename TestFixture::M;
  const Space manifold = TypeParam::make();
  std::mt19937 rng(kSeed + 31);
  const double tol = 1e-10;
  const auto q0 = TypeParam::point(manifold, rng);
  const auto far = TestFixture::cut_point(manifold, q0, rng);
  const auto easy = manifold.step(q0, random_tangent_at(manifold, q0, rng, 0.2));  // converges from the geodesic guess
  int converged = 0;
  std::string log;
  const std::array targets{far, TestFixture::beside(manifold, far, rng), easy};
  for (std::size_t target = 0; target < targets.size(); ++target) {
    const auto& qT = targets[target];
    const auto p = TestFixture::problem(manifold, q0, qT);
    for (const auto order : {SchemeOrder::First, SchemeOrder::Second}) {
      for (const bool from_rest : {false, true}) {
        cartan::SolveOptions options;
        options.method = cartan::Method::Shooting;
        options.order = order;
        options.tol = tol;
        options.max_iterations = 60;
        GeneralGuess<Space> guess;
        if (from_rest) guess.v0 = manifolds::ComponentsOf<Space>::Zero();
        const auto s = solve(p, options, guess);
        const bool passed = !s.trajectory.q.empty() && s.trajectory.t.size() >= 3 &&
                            verify_general(p, s.trajectory, s.order, tol, s.status).passed();
        if (s.converged() && target == 2 && !from_rest) ++converged;
        log += std::string(to_string(s.status)) + ": " + s.message + "\n";
        if (s.converged() || passed) {
          const double miss = manifolds::point_distance(manifold, s.trajectory.q.back(), qT);
          EXPECT_LE(miss, TestFixture::allowed(qT, tol)) << manifold.name() << ": " << s.message;
          EXPECT_LE(s.terminal_error, tol) << manifold.name();
        } else {
          EXPECT_NE(s.status, Status::Converged);
        }
      }
    }
  }
  // Not a vacuous test: the easy problem converges from the geodesic guess at both orders (the
  // others may fail: plain shooting from the cut locus of qT, or 2.5 away, is a hard start).
  EXPECT_GE(converged, 2) << manifold.name() << "\n" << log;
}

}  // namespace
}  // namespace cartan::testing
