#pragma once
// What results of every kernel share (DESIGN.md, layer "principle").

#include <limits>

namespace cartan {

/// What only collocation reports: the final mesh size, the largest relative RMS residual on it,
/// and for SO(3) max |g^T g - I| over the mesh of g and the transport element (NaN elsewhere).
struct CollocationReport {
  int mesh_size = 0;
  double max_residual = 0;
  double group_defect = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace cartan
