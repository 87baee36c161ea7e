#pragma once
// The units in which every kernel measures its unknowns (DESIGN.md, layer "principle").

#include <cmath>
#include <limits>

namespace cartan {

/// The auxiliary's own size T |v| |mu| at the geodesic velocity itself (no floor on the speed), or 0
/// where that is not a positive normal number: shooting's polish target (numerics/shooting_driver.hpp
/// ShootingDriverOptions::aux_size).
inline double aux_size(double T, double v_norm, double mu_norm) {
  const double size = T * v_norm * mu_norm;
  return std::isfinite(size) && size > std::numeric_limits<double>::min() ? size : 0.0;
}

/// The unit of the auxiliary (xi or Xi): T |v_ref| |mu_ref| (v_ref the velocity of
/// aux_scale_velocity, mu_ref its momentum at the start; the kernel computes both norms on its own
/// types), or 1 where that is not a positive normal number. For a kinetic Lagrangian the problem at
/// horizon cT is then the same dimensionless problem (methods/lie_group/shooting.hpp's header comment).
inline double aux_scale(double T, double v_ref_norm, double mu_ref_norm) {
  const double scale = aux_size(T, v_ref_norm, mu_ref_norm);
  return scale > 0 ? scale : 1.0;
}

/// The velocity at which aux_scale is taken: the geodesic velocity v, but at a speed of at least
/// 1/T (one radian over the horizon, the unit of v0 in the shooting driver), along v, or along the
/// first axis where v vanishes or is not finite. Below 1/T the auxiliary's unit would shrink like
/// |v|^2 while v0's stays 1/T: the auxiliary's rows of the dimensionless Jacobian grow like
/// 1 / (|v| T), and Levenberg–Marquardt stalled (SO(3), |log(g0^-1 gT)| = 1e-5: max-iterations) or
/// traded the boundary for the auxiliary (S^2, endpoints 1e-10 apart: a constant path within tol).
template <class Velocity>
Velocity aux_scale_velocity(const Velocity& v, double T) {
  const double speed = v.norm();
  if (speed * T >= 1 && std::isfinite(speed)) return v;
  if (speed > 0 && std::isfinite(speed)) return v / (speed * T);
  return Velocity::Unit(0) / T;
}

}  // namespace cartan
