#pragma once
// The list of groups every typed test runs over. Add a new group here.
#include <gtest/gtest.h>

#include "cartan/heisenberg.hpp"
#include "cartan/se2.hpp"
#include "cartan/se3.hpp"
#include "cartan/so3.hpp"

namespace cartan::testing {
using AllGroups = ::testing::Types<SO3, Heisenberg, SE3, SE2, SO3Generic, SE3Generic, SE2Generic>;
}
