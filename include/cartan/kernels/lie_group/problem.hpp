#pragma once
// Forwarding header, kept for one release: the problems moved to include/cartan/principle/
// (docs/architecture.md, "Layout"). Include "cartan/principle/group_problem.hpp" instead.
#include "cartan/principle/group_problem.hpp"
