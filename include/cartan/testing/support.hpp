#pragma once
// Test helpers for GoogleTest users of cartan (installed, as Ceres ships manifold_test_utils.h):
// seeded random algebra elements and a matrix comparison. Needs <gtest/gtest.h> on the include
// path and the test linked with GTest; the library itself never includes cartan/testing/.
//
//   random_tangent<G>(rng, scale)  an algebra vector with coordinates uniform in [-scale, scale]
//   random_element<G>(rng, scale)  exp of one
//   EXPECT_NEAR_MATRIX(a, b, tol)  max |a - b| over all entries <= tol (a GoogleTest expectation)

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>

#include "cartan/groups/group.hpp"

namespace cartan::testing {

/// The one seed used by every randomised check (deterministic runs, STYLE.md practice 12).
inline constexpr unsigned kSeed = 20261122u;

template <class Vec>
Vec random_vector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vec v;
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = scale * uniform(rng);
  return v;
}

template <groups::LieGroup G>
groups::TangentOf<G> random_tangent(std::mt19937& rng, double scale = 1.0) {
  return random_vector<groups::TangentOf<G>>(rng, scale);
}

template <groups::LieGroup G>
groups::ElementOf<G> random_element(std::mt19937& rng, double scale = 1.0) {
  return G::exp(random_tangent<G>(rng, scale));
}

/// max |a - b| over all entries.
template <class A, class B>
double max_abs_diff(const A& a, const B& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

}  // namespace cartan::testing

#define EXPECT_NEAR_MATRIX(a, b, tol) EXPECT_LE(::cartan::testing::max_abs_diff((a), (b)), (tol))
