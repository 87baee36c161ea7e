#pragma once
// Shared helpers for cartan's tests: seeded random algebra elements and matrix comparisons.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <initializer_list>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cartan/groups/group.hpp"

namespace cartan::testing {

/// The one seed used by every randomised test (deterministic runs, STYLE.md practice 12).
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

/// Runs `call`, expecting std::invalid_argument whose message contains every fragment (the
/// bad value's name and value, STYLE.md "errors name the value").
template <class F>
void expect_invalid(const F& call, std::initializer_list<std::string_view> fragments) {
  try {
    call();
    ADD_FAILURE() << "no std::invalid_argument thrown";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    for (std::string_view fragment : fragments) EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

template <class F>
void expect_invalid(const F& call, std::string_view fragment) {
  expect_invalid(call, {fragment});
}

}  // namespace cartan::testing

#define EXPECT_NEAR_MATRIX(a, b, tol) EXPECT_LE(::cartan::testing::max_abs_diff((a), (b)), (tol))
