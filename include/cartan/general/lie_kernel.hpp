#pragma once
// Forwarding header, kept for one release: the kernels moved to include/cartan/kernels/
// (docs/architecture.md, "Layout"). Include "cartan/methods/lie_group_as_manifold.hpp" instead.
#include "cartan/methods/lie_group_as_manifold.hpp"
