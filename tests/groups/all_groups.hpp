#pragma once
// The list of groups every typed test runs over. Add a new group here.
#include <gtest/gtest.h>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"

namespace cartan::testing {
using AllGroups = ::testing::Types<groups::SO3, groups::Heisenberg, groups::SE3, groups::SE2, groups::SO3Generic, groups::SE3Generic, groups::SE2Generic>;
}
