// The right-trivialised form of the transported principle (right_form.hpp) traces the same curve
// g(t) as the left form of eq:reduced-system (scheme.hpp): the first-order discretisations of the
// two are the same map in other coordinates (v_R = Ad(g0) v, mu_R = Ad(g0)^{-T} mu, Q = Ad(g) P
// Ad(g0)^{-1}), so the nodes g_k agree to rounding at every N, hence in the limit.
#include <gtest/gtest.h>

#include "cartan/kernels/lie_group/right_form.hpp"
#include "cartan/kernels/lie_group/sweep.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

// Rounding: each step composes O(1) elements; over N = 300 steps the two forms' nodes differ by
// ~1e-14 (measured); 1e-11 allows for the growth of rounding along unstable directions.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void expect_same_curve(const std::string& what, const L& l, std::mt19937& rng) {
  for (double lambda : {0.0, 0.3, 0.5, 1.0, 1.6}) {
    const transported::TransportedProblem<G, L> p{l, lambda, 3.0, 300, random_element<G>(rng, 0.7), G::identity()};
    const groups::TangentOf<G> v0 = random_tangent<G>(rng), xi0 = random_tangent<G>(rng, 0.5);
    const transported::TransportedScheme<G, L> scheme(p, transported::SchemeOrder::First);
    transported::TransportedTrajectory<G> left;
    transported::SweepOutput<G, L> out;
    out.trajectory = &left;
    ASSERT_TRUE(transported::forward_sweep(scheme, v0, xi0, nullptr, 0, out)) << out.failure;
    const auto ad_g0 = G::Ad(p.g0);
    const auto right = transported::right_form_sweep(p, groups::TangentOf<G>(ad_g0 * v0),
                                                     groups::CovectorOf<G>(ad_g0.inverse().transpose() * xi0));
    ASSERT_EQ(right.g.size(), left.g.size());
    double dg = 0, dv = 0, dmu = 0;
    for (std::size_t k = 0; k < left.g.size(); ++k) {
      dg = std::max(dg, max_abs_diff(right.g[k], left.g[k]));
      dv = std::max(dv, max_abs_diff(right.v[k], ad_g0 * left.v[k]));
      dmu = std::max(dmu, max_abs_diff(right.mu[k], ad_g0.inverse().transpose() * left.mu[k]));
    }
    std::cout << "[ measured ] " << what << ", lambda " << lambda << ": max |dg| " << dg << ", |dv| " << dv << ", |dmu| " << dmu
              << '\n';
    EXPECT_LE(dg, 1e-11) << what << ' ' << lambda;
    EXPECT_LE(dv, 1e-11) << what << ' ' << lambda;
    EXPECT_LE(dmu, 1e-11) << what << ' ' << lambda;
  }
}

TEST(RightForm, TracesTheSameCurveAsTheLeftForm) {
  std::mt19937 rng(kSeed + 80);
  const Eigen::Matrix3d inertia = Eigen::Vector3d(2.0, 3.0, 4.0).asDiagonal();
  expect_same_curve<groups::SO3>("SO(3) oscillator", mechanics::SO3Oscillator(inertia), rng);
  expect_same_curve<groups::Heisenberg>("H3 oscillator", mechanics::h3_oscillator(), rng);
  const Eigen::Matrix<double, 6, 1> se3_inertia = (Eigen::Matrix<double, 6, 1>() << 1.0, 2.0, 3.0, 0.5, 0.8, 1.2).finished();
  expect_same_curve<groups::SE3>("SE(3) free body", mechanics::SE3FreeBody(se3_inertia.asDiagonal().toDenseMatrix()), rng);
}

// The right form is not the left form with relabelled variables: at g0 != e its velocity is
// Ad(g0) v, and Q differs from P (negative control: feeding it the left velocity changes the curve).
TEST(RightForm, NeedsTheRightTrivialisedStart) {
  const mechanics::SO3Oscillator l(Eigen::Vector3d(2.0, 3.0, 4.0).asDiagonal());
  const transported::TransportedProblem<groups::SO3, mechanics::SO3Oscillator> p{
      l, 0.5, 2.0, 100, groups::SO3::exp(groups::SO3::Tangent(0.4, -0.3, 0.6)), groups::SO3::identity()};
  const groups::SO3::Tangent v0(0.5, 0.2, -0.7), xi0(0.1, 0.0, 0.2);
  const auto as_given = transported::right_form_sweep(p, v0, xi0);
  const auto converted = transported::right_form_sweep(p, groups::SO3::Tangent(groups::SO3::Ad(p.g0) * v0),
                                                       groups::SO3::Tangent(groups::SO3::Ad(p.g0) * xi0));
  EXPECT_GT(max_abs_diff(as_given.g.back(), converted.g.back()), 1e-2);
  expect_invalid([&] { transported::right_form_sweep(p, groups::SO3::Tangent(NAN, 0, 0), xi0); }, {"right_form_sweep", "v0"});
}

}  // namespace
}  // namespace cartan::testing
