// Typed tests of the Lie group concept over every group cartan ships.
#include <gtest/gtest-spi.h>

#include "groups/all_groups.hpp"
#include "cartan/testing/group_axioms.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

template <class G>
class GroupTest : public ::testing::Test {};
TYPED_TEST_SUITE(GroupTest, AllGroups);

TYPED_TEST(GroupTest, Axioms) { expect_group_axioms<TypeParam>(); }
TYPED_TEST(GroupTest, ExpLogAgainstMatrixExponential) { expect_exp_log<TypeParam>(); }
TYPED_TEST(GroupTest, AdjointByConjugation) { expect_adjoint<TypeParam>(); }
TYPED_TEST(GroupTest, AdIsDerivativeOfAdAndCoadIsDual) { expect_ad_and_coad<TypeParam>(); }
TYPED_TEST(GroupTest, TranslationDifferentials) { expect_translations<TypeParam>(); }
TYPED_TEST(GroupTest, LeftJacobianIsTheSeries) { expect_left_jacobian_is_the_series<TypeParam>(); }
TYPED_TEST(GroupTest, ExpJacobiansAreTheDerivatives) { expect_exp_jacobians_are_the_derivatives<TypeParam>(); }

TYPED_TEST(GroupTest, InstalledHelperPasses) { expect_lie_group<TypeParam>(); }

// A user's group whose ad has the wrong sign: the installed helper reports the checks of ad
// (against the commutator and Ad) and the adjoint's exp(ad), and no group axiom.
struct SO3WithWrongAd : groups::SO3 {
  static AlgebraMatrix ad(const Tangent& u) { return -groups::SO3::ad(u); }
};

TEST(InstalledGroupAxioms, ReportAWrongAd) {
  ::testing::TestPartResultArray failures;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    expect_group_axioms<SO3WithWrongAd>();
  }
  EXPECT_EQ(failures.size(), 0);
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    expect_ad_and_coad<SO3WithWrongAd>();
  }
  EXPECT_GT(failures.size(), 0);
}

}  // namespace
}  // namespace cartan::testing
