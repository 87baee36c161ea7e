#pragma once
// The units in which every kernel measures its unknowns (DESIGN.md, layer "principle").

#include <cmath>
#include <limits>

namespace cartan {

/// The unit of the auxiliary (xi or Xi): T |v_ref| |mu_ref| (v_ref the geodesic velocity, mu_ref
/// its momentum at the start; the kernel computes both norms on its own types), or 1 where that
/// is not a positive normal number. For a kinetic Lagrangian the problem at horizon cT is then the
/// same dimensionless problem (methods/lie_group/shooting.hpp's header comment).
inline double aux_scale(double T, double v_ref_norm, double mu_ref_norm) {
  const double scale = T * v_ref_norm * mu_ref_norm;
  return std::isfinite(scale) && scale > std::numeric_limits<double>::min() ? scale : 1.0;
}

}  // namespace cartan
