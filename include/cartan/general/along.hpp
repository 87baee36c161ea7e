#pragma once
// Forwarding header, kept for one release: the kernels moved to include/cartan/kernels/
// (docs/architecture.md, "Layout"). Include "cartan/kernels/manifold/along.hpp" instead.
#include "cartan/kernels/manifold/along.hpp"
