// Every manifold with a connection (include/cartan/manifolds) against definitions that do not use
// its Christoffel map the way the library does: transport against a Runge–Kutta integration of
// the transport equation, torsion and curvature against the parallelogram gap and the small-loop
// holonomy, the Bianchi identities with torsion, metric and dual-pairing preservation, and the
// closed forms of S^2 and H^2 (great-circle transport, triangle holonomy = +-area, K = +-1).

#include <cmath>
#include <numbers>

#include "cartan/groups/se3.hpp"
#include "cartan/manifolds/derivatives.hpp"
#include "cartan/manifolds/geometry.hpp"
#include "manifold_instances.hpp"

namespace cartan::testing {
namespace {

using namespace cartan::manifolds;

template <class Instance>
class ManifoldTest : public ::testing::Test {
 protected:
  using M = typename Instance::Manifold;
  using Point = PointOf<M>;
  using Vector = VectorOf<M>;
  using Operator = OperatorOf<M>;
  ManifoldTest() : manifold(Instance::make()) {}
  Point point() { return Instance::point(manifold, rng); }
  Vector tangent(const Point& q, double scale = 1.0) { return random_tangent_at(manifold, q, rng, scale); }
  /// The represented velocity of c(s) = step(q, s x) at s, by a central difference of `difference`.
  Vector piece_velocity(const Point& q, const Vector& x, double s) const {
    const double d = 1e-5;
    const Point c = manifold.step(q, Vector(s * x));
    return (manifold.difference(c, manifold.step(q, Vector((s + d) * x))) -
            manifold.difference(c, manifold.step(q, Vector((s - d) * x)))) / (2 * d);
  }
  /// Classical RK4 on y' = f(s, y) over [0, 1].
  template <class F>
  static Vector rk4(const F& f, Vector y, int steps) {
    const double h = 1.0 / steps;
    for (int k = 0; k < steps; ++k) {
      const double s = k * h;
      const Vector k1 = f(s, y), k2 = f(s + h / 2, Vector(y + h / 2 * k1)), k3 = f(s + h / 2, Vector(y + h / 2 * k2)),
                   k4 = f(s + h, Vector(y + h * k3));
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return y;
  }

  M manifold;
  std::mt19937 rng{kSeed};
};

TYPED_TEST_SUITE(ManifoldTest, AllManifolds);

/// Error floors of a Chart, whose transport is integrated (RK4: about 1e-11 at the tests'
/// |Gamma| |x| of order 1) and whose D Gamma is a central difference, so that nabla R differences
/// a difference: its rounding floor is eps^(2/3) / eps^(1/3) = eps^(1/3), about 1e-5 relative
/// (measured 3e-6 on the half-plane). 0 for the instances with closed forms.
template <class M>
constexpr bool is_chart = std::is_same_v<M, manifolds::Chart<M::kDim>>;
template <class M>
constexpr double transport_floor() { return is_chart<M> ? 1e-10 : 0.0; }
template <class M>
constexpr double nested_difference_floor() { return is_chart<M> ? 3e-5 : 0.0; }

TYPED_TEST(ManifoldTest, StepAndDifferenceAreInverse) {
  for (int trial = 0; trial < 5; ++trial) {
    const auto q = this->point();
    const auto x = this->tangent(q, 0.8);
    this->manifold.validate(this->manifold.step(q, x), "step");
    EXPECT_NEAR_MATRIX(this->manifold.difference(q, this->manifold.step(q, x)), x, 1e-12);
  }
}

// The closed-form transport along a piece solves y' = -Gamma_{c(s)}(c'(s), y): RK4 with 200
// steps (error ~ 1e-10 for these O(1) data) and the velocity by central differences (~ 1e-10).
TYPED_TEST(ManifoldTest, TransportAlongStepSolvesTheTransportEquation) {
  for (int trial = 0; trial < 3; ++trial) {
    const auto q = this->point();
    const auto x = this->tangent(q, 0.9), y = this->tangent(q);
    using V = typename TestFixture::Vector;
    const auto f = [&](double s, const V& z) {
      return V(-this->manifold.christoffel(this->manifold.step(q, V(s * x)), this->piece_velocity(q, x, s), z));
    };
    EXPECT_NEAR_MATRIX(this->manifold.transport_along_step(q, x) * y, TestFixture::rk4(f, y, 200), 1e-8);
  }
}

// Parallel transport of covectors is the dual of vector transport: alpha' = Gamma(c', .)^T alpha
// integrated by RK4 pairs with the library's transported vector as alpha(0) pairs with y.
TYPED_TEST(ManifoldTest, TransportPreservesTheDualPairing) {
  const auto q = this->point();
  const auto x = this->tangent(q, 0.9), y = this->tangent(q);
  using V = typename TestFixture::Vector;
  const V alpha = random_vector<V>(this->rng, 1.0);
  const auto f = [&](double s, const V& a) {
    const auto c = this->manifold.step(q, V(s * x));
    return V(christoffel_operator(this->manifold, c, this->piece_velocity(q, x, s)).transpose() * a);
  };
  const V alpha1 = TestFixture::rk4(f, alpha, 200);
  EXPECT_NEAR(alpha1.dot(this->manifold.transport_along_step(q, x) * y), alpha.dot(y), 1e-8);
}

TYPED_TEST(ManifoldTest, TransportPreservesTheMetricWhereThereIsOne) {
  for (int trial = 0; trial < 3; ++trial) {
    const auto q = this->point();
    const auto metric = metric_at(this->manifold, q);
    if (!metric) GTEST_SKIP() << "this instance has no metric";
    const auto x = this->tangent(q, 0.9), y = this->tangent(q), z = this->tangent(q);
    const auto p = this->manifold.transport_along_step(q, x);
    const auto metric1 = *metric_at(this->manifold, this->manifold.step(q, x));
    EXPECT_NEAR((p * y).dot(metric1 * (p * z)), y.dot(*metric * z), 1e-13 + transport_floor<typename TestFixture::M>());
  }
}

// Torsion is the gap of an infinitesimal parallelogram: from q, s x then s (transported y) ends
// at difference s^2 (-T(x, y)) + O(s^3) from s y then s (transported x). Richardson in s.
TYPED_TEST(ManifoldTest, TorsionIsTheParallelogramGap) {
  const auto& m = this->manifold;
  using V = typename TestFixture::Vector;
  const auto q = this->point();
  const V x = this->tangent(q), y = this->tangent(q);
  const auto gap = [&](double s) {
    const auto qx = m.step(q, V(s * x)), qy = m.step(q, V(s * y));
    const auto qxy = m.step(qx, V(s * (m.transport_along_step(q, V(s * x)) * y)));
    const auto qyx = m.step(qy, V(s * (m.transport_along_step(q, V(s * y)) * x)));
    // Pulled back to q by the transport along s x, so that gaps at different s compare.
    const V at_qx = m.difference(qx, qxy) - m.difference(qx, qyx);
    return V(m.transport_along_step(q, V(s * x)).colPivHouseholderQr().solve(at_qx) / (s * s));
  };
  const double s = 1e-2;
  const V extrapolated = 2 * gap(s / 2) - gap(s);
  EXPECT_NEAR_MATRIX(extrapolated, V(-torsion(m, q, x, y)), 2e-5 * (1 + torsion(m, q, x, y).norm()));
}

// Curvature is the holonomy of a small loop: around the image of the square [0, s]^2 under
// (a, b) -> step(q, a x + b y), travelled first along x, transport is I - s^2 R(x, y) + O(s^3).
TYPED_TEST(ManifoldTest, CurvatureIsTheSmallLoopHolonomy) {
  const auto& m = this->manifold;
  using V = typename TestFixture::Vector;
  using Op = typename TestFixture::Operator;
  const auto q = this->point();
  const V x = this->tangent(q), y = this->tangent(q), z = this->tangent(q);
  const auto holonomy = [&](double s) {
    const std::array corners{q, m.step(q, V(s * x)), m.step(q, V(s * (x + y))), m.step(q, V(s * y)), q};
    Op p = Op::Identity();
    for (int k = 0; k < 4; ++k) p = m.transport_along_step(corners[k], m.difference(corners[k], corners[k + 1])) * p;
    return V((p * z - z) / (s * s));
  };
  const double s = 1e-2;
  const V expected = -curvature(m, q, x, y, z);
  EXPECT_NEAR_MATRIX(V(2 * holonomy(s / 2) - holonomy(s)), expected, 1e-4 * (1 + expected.norm()));
}

// First Bianchi identity with torsion: cyc R(x,y)z = cyc [T(T(x,y),z) + (nabla_x T)(y,z)];
// second: cyc [(nabla_x R)(y,z) + R(T(x,y),z)] w = 0. nabla T, nabla R by central differences
// (error ~ eps^(2/3) ~ 1e-11 relative, times the data's third derivatives).
TYPED_TEST(ManifoldTest, BianchiIdentitiesWithTorsion) {
  const auto& m = this->manifold;
  using V = typename TestFixture::Vector;
  const auto q = this->point();
  const V x = this->tangent(q), y = this->tangent(q), z = this->tangent(q), w = this->tangent(q);
  const auto first = [&](const V& a, const V& b, const V& c) {
    return V(curvature(m, q, a, b, c) - torsion(m, q, V(torsion(m, q, a, b)), c) -
                  covariant_derivative_torsion(m, q, a, b, c));
  };
  EXPECT_NEAR_MATRIX(V(first(x, y, z) + first(y, z, x) + first(z, x, y)), V::Zero(), 1e-7);
  const auto second = [&](const V& a, const V& b, const V& c) {
    return V(covariant_derivative_curvature(m, q, a, b, c, w) + curvature(m, q, V(torsion(m, q, a, b)), c, w));
  };
  EXPECT_NEAR_MATRIX(V(second(x, y, z) + second(y, z, x) + second(z, x, y)), V::Zero(),
                     1e-6 + nested_difference_floor<typename TestFixture::M>());
}

// nabla T = nabla R = 0 exactly for the instances that say so (the solver's fast path), and
// measurably not for the others.
TYPED_TEST(ManifoldTest, TorsionAndCurvatureAreParallelExactlyWhenDeclared) {
  const auto& m = this->manifold;
  using V = typename TestFixture::Vector;
  double largest = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const auto q = this->point();
    const V w = this->tangent(q), x = this->tangent(q), y = this->tangent(q), z = this->tangent(q);
    largest = std::max({largest, covariant_derivative_torsion(m, q, w, x, y).norm(),
                        covariant_derivative_curvature(m, q, w, x, y, z).norm()});
  }
  if (m.has_parallel_torsion_and_curvature()) {
    EXPECT_LT(largest, 1e-7 + nested_difference_floor<typename TestFixture::M>());
  } else {
    EXPECT_GT(largest, 1e-2);
  }
}

TEST(Manifolds, FlagsOfTheInstances) {
  EXPECT_TRUE(SphereInstance::make().has_parallel_torsion_and_curvature());
  EXPECT_TRUE(SO3CartanSchouten::make().has_parallel_torsion_and_curvature());
  EXPECT_TRUE(FlatPlane::make().has_parallel_torsion_and_curvature());
  EXPECT_FALSE(SO3LeviCivita::make().has_parallel_torsion_and_curvature());
  EXPECT_FALSE(RandomEuclidean::make().has_parallel_torsion_and_curvature());
}

// Along a great circle, transport is the rotation about its axis q x u by the arc length.
TEST(Sphere, TransportAlongAGreatCircleIsTheRotationAboutItsAxis) {
  const Eigen::Vector3d q = sphere_point({0.3, -0.5, 0.8});
  const auto basis = Sphere::tangent_basis(q);
  const Eigen::Vector3d x = 1.7 * basis.col(0) + 0.4 * basis.col(1), y = basis * Eigen::Vector2d(-0.6, 1.1);
  const Eigen::Vector3d axis = q.cross(x).normalized();
  const double angle = x.norm();
  const Eigen::Vector3d rotated = std::cos(angle) * y + std::sin(angle) * axis.cross(y) +
                                  (1 - std::cos(angle)) * axis.dot(y) * axis;  // Rodrigues
  EXPECT_NEAR_MATRIX(Sphere::transport_along_step(q, x) * y, rotated, 1e-14);
  EXPECT_NEAR_MATRIX(Sphere::step(q, x), Eigen::Vector3d(std::cos(angle) * q + std::sin(angle) * x / angle), 1e-15);
}

/// Holonomy angle of the geodesic triangle a -> b -> c -> a, measured in the oriented tangent
/// plane at a, and K times the triangle's area from its angles (Gauss–Bonnet: K area = sum - pi).
template <class Q>
std::pair<double, double> triangle_holonomy_and_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                     const Eigen::Vector3d& c) {
  const std::array v{a, b, c, a};
  Eigen::Matrix3d p = Eigen::Matrix3d::Identity();
  for (int k = 0; k < 3; ++k) p = Q::transport_along_step(v[k], Q::difference(v[k], v[k + 1])) * p;
  const auto e = Q::tangent_basis(a);
  const Eigen::Vector3d y = e.col(0), py = p * y;
  const double holonomy = std::atan2(Q::inner(e.col(1), py), Q::inner(e.col(0), py));
  double angle_sum = 0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d u = Q::difference(v[k], v[(k + 1) % 3]), w = Q::difference(v[k], v[(k + 2) % 3]);
    angle_sum += std::acos(Q::inner(u, w) / std::sqrt(Q::inner(u, u) * Q::inner(w, w)));
  }
  return {holonomy, angle_sum - std::numbers::pi};
}

// Holonomy around a geodesic triangle is the rotation by K times its area, counterclockwise for a
// counterclockwise triangle (here: seen from outside S^2, and positively oriented on H^2 with the
// instance's basis).
TEST(Sphere, GeodesicTriangleHolonomyIsTheArea) {
  const Eigen::Vector3d a = sphere_point({1, 0.1, 0.2}), b = sphere_point({0.1, 1, 0.3}), c = sphere_point({0.2, 0.3, 1});
  ASSERT_GT(a.cross(b).dot(c), 0);  // counterclockwise seen from outside
  const auto [holonomy, area] = triangle_holonomy_and_area<Sphere>(a, b, c);  // K = 1
  EXPECT_GT(area, 0.5);
  EXPECT_NEAR(holonomy, area, 1e-13);
}

TEST(HyperbolicPlane, GeodesicTriangleHolonomyIsMinusTheArea) {
  const Eigen::Vector3d a = hyperbolic_point(0, 0), b = hyperbolic_point(1.5, 0.2), c = hyperbolic_point(0.3, 1.2);
  const auto [holonomy, area_times_k] = triangle_holonomy_and_area<HyperbolicPlane>(a, b, c);
  // The triangle is counterclockwise in the basis at a (e1 = x1 direction, e2 = x2 direction).
  EXPECT_LT(area_times_k, -0.2);
  EXPECT_NEAR(holonomy, area_times_k, 1e-13);
}

/// <R(x, y) y, x> / (|x|^2 |y|^2 - <x, y>^2) for random tangent x, y at q.
template <class Q>
double sectional_curvature(const Eigen::Vector3d& q, std::mt19937& rng) {
  const auto basis = Q::tangent_basis(q);
  const Eigen::Vector3d x = basis * random_vector<Eigen::Vector2d>(rng, 1.0);
  const Eigen::Vector3d y = basis * random_vector<Eigen::Vector2d>(rng, 1.0);
  return Q::inner(curvature(Q{}, q, x, y, y), x) / (Q::inner(x, x) * Q::inner(y, y) - std::pow(Q::inner(x, y), 2));
}

TEST(Quadrics, SectionalCurvatureIsPlusOrMinusOne) {
  std::mt19937 rng(kSeed);
  EXPECT_NEAR(sectional_curvature<Sphere>(sphere_point({0.2, -0.3, 0.9}), rng), 1.0, 1e-13);
  EXPECT_NEAR(sectional_curvature<HyperbolicPlane>(hyperbolic_point(0.7, -1.1), rng), -1.0, 1e-13);
}

// The default frame of a problem from q0 to qT (docs/general-connections.md#frames): on S^2 and
// H^2, e1 the unit tangent of the minimal geodesic towards qT (difference(q0, qT) normalised),
// e2 = J (q0 x e1), a J-orthonormal basis of T_q0 (right-handed with q0 on S^2); where e1 is
// undefined, the axes' tangent_basis(q0), which require_frame_towards refuses by name. Elsewhere
// always tangent_basis(q0). Exact up to rounding (1e-14 on unit vectors).
template <class Q>
void expect_frame_towards(const Eigen::Vector3d& q0, const Eigen::Vector3d& qT) {
  const Q space;
  const Eigen::Matrix<double, 3, 2> e = default_frame(space, q0, qT);
  const Eigen::Vector3d w = space.difference(q0, qT);
  EXPECT_NEAR_MATRIX(Eigen::Vector3d(e.col(0)), Eigen::Vector3d(w / std::sqrt(Q::inner(w, w))), 1e-14);
  EXPECT_NEAR(Q::inner(e.col(0), e.col(0)), 1, 1e-14);
  EXPECT_NEAR(Q::inner(e.col(1), e.col(1)), 1, 1e-14);
  EXPECT_NEAR(Q::inner(e.col(0), e.col(1)), 0, 1e-14);
  EXPECT_NEAR(Q::inner(e.col(1), q0), 0, 1e-14);
  if constexpr (std::is_same_v<Q, Sphere>) EXPECT_GT(Eigen::Vector3d(e.col(0)).cross(Eigen::Vector3d(e.col(1))).dot(q0), 0);
  EXPECT_NO_THROW(require_frame_towards(space, q0, qT, "here"));
}

TEST(Quadrics, TheDefaultFrameTurnsTowardsQT) {
  const Eigen::Vector3d q0 = sphere_point({0.2, -0.3, 0.9});
  expect_frame_towards<Sphere>(q0, sphere_point({-0.5, 0.4, 0.1}));
  expect_frame_towards<Sphere>(q0, sphere_point({-0.2, 0.3, -0.8}));  // nearly antipodal: still defined
  expect_frame_towards<HyperbolicPlane>(hyperbolic_point(0.7, -1.1), hyperbolic_point(-0.4, 2.0));
  for (const Eigen::Vector3d& qT : {q0, Eigen::Vector3d(-q0)}) {
    EXPECT_EQ(default_frame(Sphere{}, q0, qT), Sphere::tangent_basis(q0));
    expect_invalid([&] { require_frame_towards(Sphere{}, q0, qT, "here"); },
                   {"here: q0/qT = [", qT == q0 ? "are equal" : "are antipodal", "give frame0"});
  }
  // 1e-7 from -q0, where difference(q0, qT) is known to about 1e-9 only: the frame is still
  // tangent and orthonormal to rounding (1e-15), as GeneralProblem::validate asks of a frame0.
  const Eigen::Vector3d nearly_antipodal = Sphere{}.step(Eigen::Vector3d(-q0), Eigen::Vector3d(1e-7 * Sphere::tangent_basis(-q0).col(0)));
  const Eigen::Matrix<double, 3, 2> e = default_frame(Sphere{}, q0, nearly_antipodal);
  EXPECT_NEAR((e.transpose() * q0).cwiseAbs().maxCoeff(), 0, 1e-15);
  EXPECT_NEAR_MATRIX(Eigen::Matrix2d(e.transpose() * e), Eigen::Matrix2d::Identity(), 1e-15);
  const Eigen::Vector3d p = hyperbolic_point(0.7, -1.1);
  EXPECT_EQ(default_frame(HyperbolicPlane{}, p, p), HyperbolicPlane::tangent_basis(p));
  expect_invalid([&] { require_frame_towards(HyperbolicPlane{}, p, p, "here"); }, {"are equal", "give frame0"});
  const Euclidean<2> plane;  // no frame towards qT: the coordinate basis, never refused
  EXPECT_EQ(default_frame(plane, Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)), Eigen::Matrix2d::Identity());
  EXPECT_NO_THROW(require_frame_towards(plane, Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 0), "here"));
}

// The half-plane given only by its Christoffel field: the curvature computed from Gamma (with a
// central-difference D Gamma) is the constant -1 of the closed form, <R(x, y) y, x>_g =
// -(|x|^2 |y|^2 - <x, y>^2)_g, to the difference's error (~1e-9).
TEST(Chart, HalfPlaneSectionalCurvatureIsMinusOne) {
  const auto m = manifolds::poincare_half_plane();
  std::mt19937 rng(kSeed);
  for (const Eigen::Vector2d& q : {Eigen::Vector2d(0.3, 0.5), Eigen::Vector2d(-2, 3)}) {
    const Eigen::Matrix2d g = *m.metric(q);
    const Eigen::Vector2d x = random_vector<Eigen::Vector2d>(rng, 1), y = random_vector<Eigen::Vector2d>(rng, 1);
    const double area2 = x.dot(g * x) * y.dot(g * y) - std::pow(x.dot(g * y), 2);
    EXPECT_NEAR(x.dot(g * curvature(m, q, x, y, y)) / area2, -1.0, 1e-7);
  }
  expect_invalid([&] { m.validate(Eigen::Vector2d(0.3, -0.1), "q0"); }, {"q0", "outside the chart"});
  expect_invalid([] { manifolds::Chart<2>(manifolds::Chart<2>::ChristoffelField{}); }, "christoffel");
}

// A chart's default frame is orthonormal in its metric, E^T g E = I (so that l = 1/2 |v|^2 is
// 1/2 g(q', q')), the coordinate directions orthonormalised in order (E upper triangular with a
// positive diagonal): on the half-plane, y times the identity. Without a metric, the identity.
// Rounding only: a Cholesky factor and a triangular solve of a 2 x 2 matrix (1e-15).
TEST(Chart, DefaultFrameIsOrthonormalInTheMetric) {
  const auto half = manifolds::poincare_half_plane();
  EXPECT_NEAR_MATRIX(half.tangent_basis(Eigen::Vector2d(0.3, 0.5)), Eigen::Matrix2d(0.5 * Eigen::Matrix2d::Identity()), 1e-15);
  const auto metric = [](const Eigen::Vector2d& q) {
    Eigen::Matrix2d g;
    g << 2 + q.x() * q.x(), 0.7, 0.7, 1 + q.y() * q.y();
    return g;
  };
  const manifolds::Chart<2> chart([](const Eigen::Vector2d&) { return manifolds::Chart<2>::Coefficients{}; }, metric);
  const Eigen::Vector2d q(0.4, -1.3);
  const Eigen::Matrix2d e = chart.tangent_basis(q);
  EXPECT_NEAR_MATRIX(Eigen::Matrix2d(e.transpose() * metric(q) * e), Eigen::Matrix2d::Identity(), 1e-14);
  EXPECT_EQ(e(1, 0), 0.0);
  EXPECT_GT(e(0, 0), 0.0);
  EXPECT_GT(e(1, 1), 0.0);
  const manifolds::Chart<2> flat([](const Eigen::Vector2d&) { return manifolds::Chart<2>::Coefficients{}; });
  EXPECT_EQ(flat.tangent_basis(q), Eigen::Matrix2d::Identity());
  const manifolds::Chart<2> indefinite([](const Eigen::Vector2d&) { return manifolds::Chart<2>::Coefficients{}; },
                                       [](const Eigen::Vector2d&) { return Eigen::Matrix2d(Eigen::Vector2d(1, -1).asDiagonal()); });
  expect_invalid([&] { indefinite.tangent_basis(q); }, {"metric", "symmetric positive definite"});
}

TEST(GroupManifold, LeviCivitaOfTheBiInvariantMetricIsCartanSchoutenOneHalf) {
  const auto lc = manifolds::GroupManifold<groups::SO3>::levi_civita(Eigen::Matrix3d::Identity());
  const auto cs = manifolds::GroupManifold<groups::SO3>::cartan_schouten(0.5);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR_MATRIX(lc.connection().coefficients()[i], cs.connection().coefficients()[i], 1e-15);
  EXPECT_TRUE(lc.has_parallel_torsion_and_curvature());
}

// GroupManifold::coefficients reads alpha(e_i, e_j) = sum_k alpha[(i n + j) n + k] e_k: the numbers of
// lambda [e_i, e_j] on SE(3) (a non-compact group with a non-trivial bracket in every block) give the
// Cartan–Schouten connection's Christoffel map (the same products, summed in another order: a few
// roundings of terms of size 1).
TEST(GroupManifold, CoefficientsInIJKOrderAreTheBilinearMap) {
  using G = groups::SE3;
  constexpr int n = G::kDim;
  const double lambda = 0.3;
  std::vector<double> alpha;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Eigen::Matrix<double, n, 1> value =
          lambda * groups::bracket<G>(Eigen::Matrix<double, n, 1>::Unit(i), Eigen::Matrix<double, n, 1>::Unit(j));
      for (int k = 0; k < n; ++k) alpha.push_back(value[k]);
    }
  }
  const auto from_numbers = manifolds::GroupManifold<G>::coefficients(alpha);
  const auto cs = manifolds::GroupManifold<G>::cartan_schouten(lambda);
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::Matrix<double, n, 1> x = random_vector<Eigen::Matrix<double, n, 1>>(rng, 1);
    const Eigen::Matrix<double, n, 1> y = random_vector<Eigen::Matrix<double, n, 1>>(rng, 1);
    EXPECT_NEAR_MATRIX(from_numbers.christoffel(G::identity(), x, y), cs.christoffel(G::identity(), x, y), 1e-14);
  }
  EXPECT_TRUE(from_numbers.has_parallel_torsion_and_curvature());
  alpha.pop_back();
  expect_invalid([&] { manifolds::GroupManifold<G>::coefficients(alpha); }, {"alpha", "215 numbers", "n^3 = 216"});
  alpha.push_back(std::nan(""));
  expect_invalid([&] { manifolds::GroupManifold<G>::coefficients(alpha); }, {"alpha", "finite"});
}

// The derivative of the matrix exponential (the transport derivative of constant connections) by
// its series (small A) and by the block formula (large A), against fourth-order differences of
// Eigen's exp (error ~1e-12 relative at step 1e-3 for |A| up to 3).
TEST(ExpDerivative, SeriesAndBlockFormulaMatchDifferences) {
  std::mt19937 rng(kSeed);
  for (const double size : {1e-3, 0.1, 0.4, 1.0, 3.0}) {
    const Eigen::Matrix3d a = random_vector<Eigen::Matrix<double, 9, 1>>(rng, size / 3).reshaped(3, 3);
    const Eigen::Matrix3d da = random_vector<Eigen::Matrix<double, 9, 1>>(rng, 1).reshaped(3, 3);
    const double s = 1e-3;
    const auto at = [&](double e) { return Eigen::Matrix3d(Eigen::Matrix3d(a + e * da).exp()); };
    const Eigen::Matrix3d reference = (8 * (at(s) - at(-s)) - (at(2 * s) - at(-2 * s))) / (12 * s);
    EXPECT_LT((exp_derivative<3>(a, da) - reference).norm(), 1e-10 * reference.norm()) << size;
  }
}

TEST(GroupManifold, LeviCivitaIsTorsionFree) {
  const auto lc = SO3LeviCivita::make();
  std::mt19937 rng(kSeed);
  const Eigen::Vector3d x = random_vector<Eigen::Vector3d>(rng, 1), y = random_vector<Eigen::Vector3d>(rng, 1);
  EXPECT_NEAR_MATRIX(torsion(lc, groups::SO3::identity(), x, y), Eigen::Vector3d::Zero(), 1e-15);
}

TEST(Manifolds, BadInputIsRejectedWithTheValue) {
  using SO3M = manifolds::GroupManifold<groups::SO3>;
  expect_invalid([] { SO3M::levi_civita(Eigen::Vector3d(1, -2, 4).asDiagonal()); }, {"metric", "positive definite"});
  expect_invalid([] { SO3M(connections::cartan_schouten<groups::SO3>(0.5, groups::Side::Right)); }, "side");
  expect_invalid([] { Sphere::validate(Eigen::Vector3d(1, 1, 0), "q0"); }, {"q0", "unit sphere"});
  expect_invalid([] { manifolds::HyperbolicPlane::validate(Eigen::Vector3d(0, 0, -1), "q0"); }, {"q0", "upper sheet"});
  expect_invalid([] { sphere_point(Eigen::Vector3d::Zero()); }, "nonzero");
  manifolds::Euclidean<2>::Coefficients bad;
  bad[0].setZero();
  bad[1].setConstant(std::nan(""));
  expect_invalid([&] { manifolds::Euclidean<2>{bad}; }, "coefficients[1]");
}

}  // namespace
}  // namespace cartan::testing
