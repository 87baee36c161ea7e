// The global Euler–Lagrange equation with a connection (EL-Lie), trivialised term by term
// (proof of thm-EP), against Euler–Poincaré: numerical evidence that the connection-dependent
// terms cancel for any left- or right-invariant connection (thm-EP, remark in "Right formalism").
#include <gtest/gtest.h>

#include "cartan/connections/cartan_schouten.hpp"
#include "cartan/mechanics/euler_lagrange.hpp"
#include "cartan/mechanics/euler_poincare.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "mechanics/mechanics_support.hpp"

namespace cartan::testing {
namespace {

// (EL-Lie) with each connection reproduces eq:EP-left / eq:EP-right (same side, same model).
// Both runs take identical RKMK4 steps; their momentum rates differ only by the rounding of
// the cancelling connection terms, each O(|nabla| |v| |mu|) ~ 1-10, so ~1e-15 per evaluation.
// Over 400 steps of T = 10 these errors add up (and are carried by the flow, which is at most
// mildly expanding here) to at most 2e-14 (measured; exactly 0 for lambda = 0 and 1, whose
// terms cancel bit for bit); 1e-11 leaves room for other compilers and flags.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
void expect_connection_independence(const std::string& model, const L& l, groups::Side side, const groups::ElementOf<G>& g0,
                                    const groups::TangentOf<G>& v0) {
  const auto reference = mechanics::euler_poincare<G>(side, l, g0, v0, 10.0, 400);
  for (const auto& [name, connection] : connections_on<G>(side)) {
    expect_same_trajectory<G>(model + ", " + std::string(to_string(side)) + ", " + name, reference,
                              mechanics::euler_lagrange<G>(connection, l, g0, v0, 10.0, 400), 1e-11);
  }
}

TEST(EulerLagrange, ConnectionTermsCancelOnSO3) {
  const groups::SO3::Element g0 = groups::SO3::exp(groups::SO3::Tangent(0.3, -0.5, 0.4));
  const groups::SO3::Tangent v0(0.9, -0.6, 0.7);
  const mechanics::RigidBody body(kInertia);
  const mechanics::SO3Oscillator oscillator(kInertia);
  expect_connection_independence<groups::SO3>("free body", body, groups::Side::Left, g0, v0);
  expect_connection_independence<groups::SO3>("free body", mechanics::SpatialRigidBody(body), groups::Side::Right, g0, groups::SO3::Tangent(g0 * v0));
  expect_connection_independence<groups::SO3>("SO(3) oscillator", oscillator, groups::Side::Left, g0, v0);
  expect_connection_independence<groups::SO3>("SO(3) oscillator", mechanics::right_reduced_lagrangian<groups::SO3>(oscillator), groups::Side::Right,
                                      g0, groups::SO3::Tangent(g0 * v0));
}

TEST(EulerLagrange, ConnectionTermsCancelOnH3) {
  const groups::Heisenberg::Element g0(0.3, -0.5, 0.2);
  const groups::Heisenberg::Tangent v0(0.4, 0.7, -0.3);
  const mechanics::H3Oscillator oscillator = mechanics::h3_oscillator();
  expect_connection_independence<groups::Heisenberg>("H3 oscillator", oscillator, groups::Side::Left, g0, v0);
  expect_connection_independence<groups::Heisenberg>("H3 oscillator", mechanics::right_reduced_lagrangian<groups::Heisenberg>(oscillator),
                                             groups::Side::Right, g0, groups::Heisenberg::Tangent(groups::Heisenberg::Ad(g0) * v0));
}

// The cancellation is not trivial: for the non-Cartan map every term is O(1) on its own, and
// they combine to the EP rate +-ad*_v mu + zeta only in the sum (to rounding, 1e-14).
TEST(EulerLagrange, TermsAreLargeButSumToTheEulerPoincareRate) {
  std::mt19937 rng(kSeed + 40);
  for (groups::Side side : {groups::Side::Left, groups::Side::Right}) {
    const auto connection = non_cartan_connection<groups::SO3>(side);
    for (int trial = 0; trial < 5; ++trial) {
      const groups::SO3::Tangent v = random_tangent<groups::SO3>(rng, 2.0), mu = random_tangent<groups::SO3>(rng, 2.0),
                         zeta = random_tangent<groups::SO3>(rng);
      const auto terms = mechanics::euler_lagrange_terms<groups::SO3>(connection, v, mu, zeta);
      EXPECT_GT(terms.covariant.norm(), 0.05);
      EXPECT_GT(terms.torsion.norm(), 0.05);
      EXPECT_GT((terms.horizontal - zeta).norm(), 0.05);
      EXPECT_NEAR_MATRIX(terms.momentum_rate(), mechanics::coadjoint_momentum_rate<groups::SO3>(side, v, mu, zeta), 1e-13);
    }
  }
}

}  // namespace
}  // namespace cartan::testing
