#pragma once
// The list of groups every typed test runs over. Add a new group here.
#include <gtest/gtest.h>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"

namespace cartan::testing {
/// Every group with code of its own: the closed forms and the three generic matrix groups
/// (MatrixLieGroup over three bases). The group axioms (test_group_axioms.cpp) run over these.
using AllGroups = ::testing::Types<groups::SO3, groups::Heisenberg, groups::SE3, groups::SE2, groups::SO3Generic, groups::SE3Generic, groups::SE2Generic>;
/// For suites of code written once over the group concept (transport, connections): the closed
/// forms and one generic group. The other two generic groups would only repeat MatrixLieGroup's
/// instantiation with another basis; their exp, log, Ad and Jacobians are the axiom suite's and
/// test_matrix_group.cpp's (against the closed forms), and each costs the suites about a seventh
/// of their compile time (bench/README.md, "Build time").
using GroupsWithOneGeneric = ::testing::Types<groups::SO3, groups::Heisenberg, groups::SE3, groups::SE2, groups::SE2Generic>;
}
