#pragma once
// The manifolds with connections the typed tests run over, each with a seeded way to draw points
// and tangent vectors: every instance of include/cartan/manifolds/.

#include <random>

#include "cartan/groups/se2.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/groups/heisenberg.hpp"
#include "cartan/manifolds/chart.hpp"
#include "cartan/manifolds/euclidean.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "test_support.hpp"

namespace cartan::testing {

/// A random tangent vector at q: components in the instance's tangent basis.
template <manifolds::ManifoldWithConnection M>
manifolds::VectorOf<M> random_tangent_at(const M& m, const manifolds::PointOf<M>& q, std::mt19937& rng,
                                         double scale = 1.0) {
  return m.tangent_basis(q) * random_vector<manifolds::ComponentsOf<M>>(rng, scale);
}

/// R^3 with random constant Christoffel symbols (torsion, curvature and nabla R all nonzero).
struct RandomEuclidean {
  using Manifold = manifolds::Euclidean<3>;
  static Manifold make() {
    std::mt19937 rng(kSeed);
    Manifold::Coefficients c;
    for (auto& g : c) g = random_vector<Eigen::Matrix<double, 9, 1>>(rng, 0.5).reshaped(3, 3);
    return Manifold(c);
  }
  static Manifold::Point point(const Manifold&, std::mt19937& rng) { return random_vector<Eigen::Vector3d>(rng, 2.0); }
};

struct FlatPlane {
  using Manifold = manifolds::Euclidean<2>;
  static Manifold make() { return Manifold(); }
  static Manifold::Point point(const Manifold&, std::mt19937& rng) { return random_vector<Eigen::Vector2d>(rng, 2.0); }
};

struct SphereInstance {
  using Manifold = manifolds::Sphere;
  static Manifold make() { return {}; }
  static Manifold::Point point(const Manifold&, std::mt19937& rng) {
    return manifolds::sphere_point(random_vector<Eigen::Vector3d>(rng, 1.0));
  }
};

struct HyperbolicInstance {
  using Manifold = manifolds::HyperbolicPlane;
  static Manifold make() { return {}; }
  static Manifold::Point point(const Manifold&, std::mt19937& rng) {
    const Eigen::Vector2d x = random_vector<Eigen::Vector2d>(rng, 1.5);
    return manifolds::hyperbolic_point(x[0], x[1]);
  }
};

/// The Poincare half-plane given in its chart (a field of Christoffel symbols, RK4 transport).
struct HalfPlaneChart {
  using Manifold = manifolds::Chart<2>;
  static Manifold make() { return manifolds::poincare_half_plane(); }
  static Manifold::Point point(const Manifold&, std::mt19937& rng) {
    const Eigen::Vector2d x = random_vector<Eigen::Vector2d>(rng, 1.0);
    return {x[0], 1.5 + 0.5 * x[1]};  // y in [1, 2]: pieces of the tests stay in y > 0
  }
};

/// A chart with a connection that is neither metric nor torsion-free nor parallel: Gamma^k_ij(q)
/// = A^k_ij + (q . c) B^k_ij with random A, B.
struct VaryingChart {
  using Manifold = manifolds::Chart<2>;
  /// Compiled apart, optimised (manifold_instances.cpp, the library cartan_test_instances): its
  /// Christoffel callback runs at every stage of the chart's transport, and a suite compiled at
  /// -O0 under the sanitizers spent 34 s in it (tests/CMakeLists.txt).
  static Manifold make();
  static Manifold::Point point(const Manifold&, std::mt19937& rng) { return random_vector<Eigen::Vector2d>(rng, 1.0); }
};

template <groups::LieGroup G>
struct GroupPoints {
  static groups::ElementOf<G> point(const manifolds::GroupManifold<G>&, std::mt19937& rng) {
    return G::exp(random_vector<groups::TangentOf<G>>(rng, 1.0));
  }
};

struct SO3CartanSchouten : GroupPoints<groups::SO3> {
  using Manifold = manifolds::GroupManifold<groups::SO3>;
  static Manifold make() { return Manifold::cartan_schouten(0.3); }
};

struct HeisenbergCartanSchouten : GroupPoints<groups::Heisenberg> {
  using Manifold = manifolds::GroupManifold<groups::Heisenberg>;
  static Manifold make() { return Manifold::cartan_schouten(0.7); }
};

/// The Levi-Civita connection of a left-invariant metric that is not bi-invariant.
struct SO3LeviCivita : GroupPoints<groups::SO3> {
  using Manifold = manifolds::GroupManifold<groups::SO3>;
  static Manifold make() { return Manifold::levi_civita(Eigen::Vector3d(1, 2, 4).asDiagonal()); }
};

/// A random left-invariant connection on SE(2).
struct SE2Random : GroupPoints<groups::SE2> {
  using Manifold = manifolds::GroupManifold<groups::SE2>;
  static Manifold make() {
    std::mt19937 rng(kSeed + 1);
    connections::InvariantConnection<groups::SE2>::Coefficients c;
    for (auto& g : c) g = random_vector<Eigen::Matrix<double, 9, 1>>(rng, 0.5).reshaped(3, 3);
    return Manifold(connections::InvariantConnection<groups::SE2>(groups::Side::Left, c));
  }
};

using AllManifolds = ::testing::Types<RandomEuclidean, FlatPlane, SphereInstance, HyperbolicInstance, HalfPlaneChart,
                                      VaryingChart, SO3CartanSchouten, HeisenbergCartanSchouten, SO3LeviCivita, SE2Random>;

}  // namespace cartan::testing
