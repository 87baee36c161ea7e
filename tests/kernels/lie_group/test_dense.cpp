// Dense output (kernels/lie_group/dense.hpp) against closed forms: along a one-parameter subgroup
// g(t) = g0 exp(t w) with constant v, mu, xi both interpolants (the discrete schemes' geodesic
// one and collocation's Hermite chart with the body velocity u = w) are exact; at the nodes the
// samples come back bit for bit; linear data are interpolated linearly by the discrete schemes.
#include <gtest/gtest.h>

#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/kernels/lie_group/dense.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

/// g_k = g0 exp(t_k w) at uneven times on [0, 1], v = w (lambda = 0: P = I, u = v), mu = 2 w,
/// xi = (1 - t) e_0 (linear).
template <groups::LieGroup G>
transported::TransportedTrajectory<G> subgroup(const groups::TangentOf<G>& w, const groups::ElementOf<G>& g0) {
  transported::TransportedTrajectory<G> x;
  for (double t : {0.0, 0.1, 0.25, 0.3, 0.55, 0.8, 1.0}) {
    x.t.push_back(t);
    x.g.push_back(G::compose(g0, G::exp(t * w)));
    x.v.push_back(w);
    x.mu.push_back(2 * w);
    x.xi.push_back((1 - t) * groups::CovectorOf<G>::Unit(0));
  }
  return x;
}

template <groups::LieGroup G>
void expect_exact_on_a_subgroup(const groups::TangentOf<G>& w, const groups::ElementOf<G>& g0) {
  const auto x = subgroup<G>(w, g0);
  const std::vector<double> times{0.05, 0.2, 0.29, 0.4, 0.7, 0.95};
  for (transported::Method method : {transported::Method::Shooting, transported::Method::Collocation}) {
    const transported::TransportedTrajectory<G> d = transported::dense_output<G>(x, 0.0, method, times);
    ASSERT_EQ(d.g.size(), times.size());
    for (std::size_t j = 0; j < times.size(); ++j) {
      // exp-log round trips on steps of length <= 0.25 |w|: 1e-14.
      EXPECT_NEAR_MATRIX(G::matrix(d.g[j]), G::matrix(G::compose(g0, G::exp(times[j] * w))), 1e-14) << to_string(method);
      EXPECT_NEAR_MATRIX(d.v[j], w, 1e-14) << to_string(method);
      EXPECT_NEAR_MATRIX(d.mu[j], 2 * w, 1e-14) << to_string(method);
    }
    // The discrete schemes interpolate xi linearly: exact for linear xi.
    if (method == transported::Method::Shooting) EXPECT_NEAR(d.xi[3][0], 1 - 0.4, 1e-15);
  }
}

TEST(DenseOutput, ExactAlongAOneParameterSubgroup) {
  expect_exact_on_a_subgroup<groups::SO3>(groups::SO3::Tangent(0.7, -1.2, 0.4), groups::SO3::exp(groups::SO3::Tangent(0.1, 0.2, 0.3)));
  groups::SE3::Tangent w;
  w << 0.3, -0.2, 0.5, 0.9, 0.1, -0.6;
  expect_exact_on_a_subgroup<groups::SE3>(w, groups::SE3::identity());
}

TEST(DenseOutput, NodesComeBackBitForBitAndTimesOutsideAreRefused) {
  const auto x = subgroup<groups::SO3>(groups::SO3::Tangent(0.7, -1.2, 0.4), groups::SO3::identity());
  for (transported::Method method : {transported::Method::TwoLevel, transported::Method::Collocation}) {
    const auto d = transported::dense_output<groups::SO3>(x, 0.5, method, x.t);
    for (std::size_t k = 0; k < x.t.size(); ++k) {
      EXPECT_EQ(d.g[k], x.g[k]);
      EXPECT_EQ(d.v[k], x.v[k]);
      EXPECT_EQ(d.mu[k], x.mu[k]);
      EXPECT_EQ(d.xi[k], x.xi[k]);
    }
    for (double t : {-1e-9, 1 + 1e-9, std::nan("")}) {
      expect_invalid([&] { (void)transported::dense_output<groups::SO3>(x, 0.5, method, {t}, "SolveResult.sol"); },
                     {"SolveResult.sol: t = ", "is outside [0, T] = [0, 1]"});
    }
  }
  transported::TransportedTrajectory<groups::SO3> one;
  one.t = {0};
  one.g = {groups::SO3::identity()};
  one.v = one.mu = one.xi = {groups::SO3::Tangent::Zero()};
  expect_invalid([&] { (void)transported::dense_output<groups::SO3>(one, 0.5, transported::Method::Shooting, {0.0}); },
                 "1 samples");
}

}  // namespace
}  // namespace cartan::testing
