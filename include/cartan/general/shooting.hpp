#pragma once
// Forwarding header, kept for one release: the kernels moved to include/cartan/kernels/
// (docs/architecture.md, "Layout"). Include "cartan/methods/manifold/shooting.hpp" instead.
#include "cartan/methods/manifold/shooting.hpp"
