#pragma once
// Forwarding header, kept for one release: the kernels moved to include/cartan/kernels/
// (docs/architecture.md, "Layout"). Include "cartan/kernels/lie_group/action.hpp" instead.
#include "cartan/kernels/lie_group/action.hpp"
