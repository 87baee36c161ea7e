// Built against an installed cartan: a user's tests of a group, a connection and a Lagrangian with
// the installed helpers (cartan/testing/*.hpp, GoogleTest) and check_lagrangian.
#include <cartan/connections/cartan_schouten.hpp>
#include <cartan/groups/so3.hpp>
#include <cartan/mechanics/check_lagrangian.hpp>
#include <cartan/mechanics/rigid_body.hpp>
#include <cartan/testing/connection_identities.hpp>
#include <cartan/testing/group_axioms.hpp>

using cartan::groups::SO3;

TEST(Consumer, SO3IsALieGroup) { cartan::testing::expect_lie_group<SO3>(); }

TEST(Consumer, ConnectionIdentities) {
  cartan::testing::expect_connection_identities<SO3>(cartan::connections::cartan_schouten<SO3>(0.3));
}

TEST(Consumer, OscillatorPassesCheckLagrangian) {
  const auto report = cartan::mechanics::check_lagrangian<SO3>(cartan::mechanics::SO3Oscillator(Eigen::Matrix3d::Identity()));
  EXPECT_TRUE(report.ok()) << report.text();
}
