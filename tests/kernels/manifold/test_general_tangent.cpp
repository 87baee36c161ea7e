// The tangent-linear sweep of the general scheme (kernels/manifold/tangent.hpp) against central
// differences of whole primal sweeps, on every manifold instance, both orders, the fast path and
// the general path (WithoutFastPath), with and without a potential; and shooting with it against
// shooting with forward differences (the same root, fewer sweeps).

#include <random>

#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "manifolds/manifold_instances.hpp"
#include "general_cases.hpp"

namespace cartan::testing {
namespace {

using namespace cartan::general;

/// (terminal_residual, Xi_N reshaped) as a function of (v0, Xi0 reshaped), and its Jacobian by
/// the tangent-linear sweep.
template <class M, class L>
struct ShootingMap {
  static constexpr int m = M::kDim, n = m + m * m;
  GeneralScheme<M, L> scheme;
  GeneralSchemeTangent<M, L> tangent{scheme};

  ShootingMap(const GeneralProblem<M, L>& problem, SchemeOrder order) : scheme(problem, order) {}

  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const {
    std::string failure;
    const auto last = general_sweep(scheme, manifolds::ComponentsOf<M>(x.head<m>()),
                                    manifolds::ComponentMatrixOf<M>(x.tail<m * m>().reshaped(m, m)), failure);
    EXPECT_TRUE(last) << failure;
    Eigen::VectorXd r(n);
    r << scheme.terminal_residual(*last), last->Xi.reshaped();
    return r;
  }
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x) const {
    std::string failure;
    Eigen::MatrixXd j;
    const auto last = general_sweep(scheme, manifolds::ComponentsOf<M>(x.head<m>()),
                                    manifolds::ComponentMatrixOf<M>(x.tail<m * m>().reshaped(m, m)), failure,
                                    static_cast<GeneralTrajectory<M>*>(nullptr), &tangent, &j);
    EXPECT_TRUE(last) << failure;
    return j;
  }
  /// Fourth-order central differences of whole sweeps (error ~ eps^(4/5) relative per column).
  Eigen::MatrixXd differences(const Eigen::VectorXd& x) const {
    Eigen::MatrixXd j(n, n);
    const double s = 1e-3;
    for (int c = 0; c < n; ++c) {
      const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, c) * s;
      j.col(c) = (8 * ((*this)(x + e) - (*this)(x - e)) - ((*this)(x + 2 * e) - (*this)(x - 2 * e))) / (12 * s);
    }
    return j;
  }
};

/// The worst column error of `j` against `reference`, relative to the reference's largest entry.
double relative_error(const Eigen::MatrixXd& j, const Eigen::MatrixXd& reference) {
  return (j - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

template <class Instance>
class GeneralTangentTest : public ::testing::Test {
 protected:
  using M = typename Instance::Manifold;
  static constexpr int m = M::kDim;

  /// A problem between a random point and a point about 0.6 away, with a random A (SPD), and the
  /// unknowns (v0, Xi0) at the geodesic guess plus a random Xi0.
  template <class Manifold>
  std::pair<GeneralProblem<Manifold, KineticPotential<Manifold>>, Eigen::VectorXd> problem(const Manifold& manifold,
                                                                                          const M& inner) {
    std::mt19937 rng(kSeed + 7);
    const auto q0 = Instance::point(inner, rng);
    const auto qT = inner.step(q0, random_tangent_at(inner, q0, rng, 0.6));
    const Eigen::Matrix<double, m, m> b = random_vector<Eigen::Matrix<double, m * m, 1>>(rng, 0.3).reshaped(m, m);
    const Eigen::Matrix<double, m, m> a = Eigen::Matrix<double, m, m>::Identity() + b * b.transpose();
    GeneralProblem<Manifold, KineticPotential<Manifold>> p{manifold, KineticPotential<Manifold>(a), 1.0, 12, q0, qT,
                                                           std::nullopt};
    Eigen::VectorXd x(m + m * m);
    x << geodesic_guess(p), random_vector<Eigen::Matrix<double, m * m, 1>>(rng, 0.3);
    return {p, x};
  }

  // The differences' error is ~1e-12 relative; the sweep's own local derivatives are closed forms
  // or central differences of the instance's functions (~eps^(2/3) ~ 4e-11 each, summed over 12
  // steps, times the O(1) conditioning of the map): measured 4e-12 to 7e-10 on every instance.
  // A Chart's RK4 transport changes its step count with |x| (chart.hpp), a jump of ~1e-11 that a
  // difference of step 1e-3 turns into ~1e-8: 1e-6 there, 1e-8 elsewhere.
  //
  // On a shipped manifold the sweep is the library's, compiled for the erased Lagrangian
  // (compiled.hpp; the erased particle forwards its closed-form Hessian): what the CLI and Python
  // run, and no instantiation of the sweep in this unit. WithoutFastPath is this test's own type.
  template <class Manifold>
  void check(const Manifold& manifold, const M& inner, SchemeOrder order) {
    const auto [p, x] = problem(manifold, inner);
    const double tolerance = std::is_same_v<M, manifolds::Chart<m>> ? 1e-6 : 1e-8;
    const auto expect_tangent = [&](const auto& map, const Eigen::VectorXd& at) {
      EXPECT_LT(relative_error(map.jacobian(at), map.differences(at)), tolerance) << manifold.name();
    };
    if constexpr (std::is_same_v<Manifold, M>) {
      expect_tangent(ShootingMap<M, ErasedLagrangian<M>>(erased(p), order), x);
    } else {
      expect_tangent(ShootingMap<Manifold, KineticPotential<Manifold>>(p, order), x);
    }
  }
};

TYPED_TEST_SUITE(GeneralTangentTest, AllManifolds);

TYPED_TEST(GeneralTangentTest, JacobianMatchesDifferencesOfSweeps) {
  const auto manifold = TypeParam::make();
  this->check(manifold, manifold, SchemeOrder::First);
  this->check(manifold, manifold, SchemeOrder::Second);
}

// Without the fast path the connection terms are recomputed at every node and differentiated
// through the dual frame and the point. The instances without a fast path (random R^3, the varying
// chart, Levi-Civita on SO(3), random SE(2)) take this path above; here the three kinds of the
// other instances, one of each (compile time is the cost of each instantiation): an embedding
// (the dual frame's normal term), a left-invariant connection (T, R on the ambient basis computed
// once) and a chart (point derivatives by differences).
template <class Instance>
class GeneralTangentGeneralPathTest : public GeneralTangentTest<Instance> {};
using FastPathKinds = ::testing::Types<SphereInstance, SO3CartanSchouten, HalfPlaneChart>;
TYPED_TEST_SUITE(GeneralTangentGeneralPathTest, FastPathKinds);

TYPED_TEST(GeneralTangentGeneralPathTest, JacobianMatchesDifferencesOfSweeps) {
  const auto manifold = TypeParam::make();
  ASSERT_TRUE(manifold.has_parallel_torsion_and_curvature());
  const WithoutFastPath<typename TypeParam::Manifold> general{manifold};
  this->check(general, manifold, SchemeOrder::First);
  this->check(general, manifold, SchemeOrder::Second);
}

// The spherical pendulum: the potential's Hessian (a difference of its gradient) in the sweep.
TEST(GeneralTangent, JacobianWithAPotentialOnTheSphere) {
  using manifolds::Sphere;
  const Eigen::Vector3d q0 = manifolds::sphere_point({1, 0.2, -0.3}), qT = manifolds::sphere_point({0.3, 1, 0.2});
  const auto l = KineticPotential<Sphere>::with_linear_potential(Eigen::Vector2d(1, 3).asDiagonal(), {0, 0, 9.81});
  const auto p = erased(GeneralProblem<Sphere, KineticPotential<Sphere>>{Sphere{}, l, 1.2, 16, q0, qT, std::nullopt});
  for (const SchemeOrder order : {SchemeOrder::First, SchemeOrder::Second}) {
    const ShootingMap<Sphere, ErasedLagrangian<Sphere>> map(p, order);
    Eigen::VectorXd x(6);
    x << geodesic_guess(p), 0.1, -0.2, 0.3, 0.05;
    EXPECT_LT(relative_error(map.jacobian(x), map.differences(x)), 1e-8);  // as above
  }
}

// A Lie-group model with a group gradient (the paper's SO(3) oscillator) under the Levi-Civita
// connection of a non-bi-invariant metric: the model's own second derivatives through OnGroupManifold.
TEST(GeneralTangent, JacobianOfTheOscillatorUnderLeviCivita) {
  using SO3M = manifolds::GroupManifold<groups::SO3>;
  using Top = OnGroupManifold<groups::SO3, mechanics::SO3Oscillator>;
  const SO3M manifold = SO3M::levi_civita(Eigen::Vector3d(1, 2, 4).asDiagonal());
  const Top top{mechanics::SO3Oscillator(paper_inertia())};
  const auto p = erased(GeneralProblem<SO3M, Top>{manifold, top, 1.0, 10, groups::SO3::identity(),
                                                  groups::SO3::exp(Eigen::Vector3d(0.4, -0.2, 0.5)), std::nullopt});
  const ShootingMap<SO3M, ErasedLagrangian<SO3M>> map(p, SchemeOrder::Second);
  Eigen::VectorXd x(12);
  x << geodesic_guess(p), Eigen::VectorXd::LinSpaced(9, -0.2, 0.3);
  EXPECT_LT(relative_error(map.jacobian(x), map.differences(x)), 1e-8);  // as above
}

// Shooting with the tangent-linear Jacobian reaches the root that forward differences reach, in
// fewer sweeps (one per Jacobian instead of 1 + m + m^2).
TEST(GeneralTangent, ShootingFindsTheSameRootInFewerSweeps) {
  using SO3M = manifolds::GroupManifold<groups::SO3>;
  const auto reference = paper_free_body(0.0, 100, 3);
  const auto p = erased(free_body_on(SO3M::levi_civita(Eigen::Vector3d(1, 2, 3).asDiagonal()), reference));
  GeneralShootingOptions options;
  options.order = SchemeOrder::Second;
  options.tolerance = 1e-11;
  const auto tangent = solve_general_shooting(p, options);
  options.analytic_jacobian = false;
  const auto differences = solve_general_shooting(p, options);
  ASSERT_TRUE(tangent.converged()) << tangent.message;
  ASSERT_TRUE(differences.converged()) << differences.message;
  // Both roots satisfy |r| <= 1e-11 with an O(1)-conditioned map: they agree to ~1e-10.
  EXPECT_LT((tangent.v0 - differences.v0).norm(), 1e-9);
  EXPECT_LT((tangent.Xi0 - differences.Xi0).norm(), 1e-8);
  EXPECT_LT(tangent.sweeps * 3, differences.sweeps) << tangent.message << "\n" << differences.message;
}

}  // namespace
}  // namespace cartan::testing
