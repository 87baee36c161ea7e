#pragma once
// Forwarding header, kept for one release: the manifold Lagrangians moved to include/cartan/mechanics/
// (docs/architecture.md, "Layout"). Include "cartan/mechanics/manifold_check_lagrangian.hpp" instead.
#include "cartan/mechanics/manifold_check_lagrangian.hpp"
