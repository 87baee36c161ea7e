// Typed tests of the Lie group concept over every group cartan ships.
#include "groups/all_groups.hpp"
#include "groups/group_axioms.hpp"

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

}  // namespace
}  // namespace cartan::testing
