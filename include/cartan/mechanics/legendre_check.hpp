#pragma once
// The check every solve makes of a Lagrangian before any work (docs/design/one-core.md D11):
// its `velocity` must invert its `momentum`, since the schemes recover the velocity from the
// momentum with it at every step. A Lagrangian written by hand (in C++ or Python) whose two maps
// disagree would otherwise give a converged, wrong answer.

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>

#include "cartan/errors.hpp"

namespace cartan::mechanics {

/// Throws std::invalid_argument ("<where>: lagrangian = (velocity(t, g, momentum(t, g, v)) = ...
/// for v = ... at t = ...) does not invert its momentum: ...") unless velocity(t, x,
/// momentum(t, x, v)) = v to 1e-6 relative at each (t, x) of `at`, for v = `typical` (when given,
/// first) and the basis vectors. An exact inverse agrees to rounding, an iterative one to its
/// own tolerance, which should be far below the solver's.
template <class Lagrangian, class Point, class Velocity>
void check_legendre_inverse(const char* where, const Lagrangian& lagrangian,
                            std::initializer_list<std::pair<double, Point>> at, const std::optional<Velocity>& typical) {
  for (const auto& [t, x] : at) {
    for (int i = typical ? -1 : 0; i < Velocity::RowsAtCompileTime; ++i) {
      const Velocity v = i < 0 ? *typical : Velocity(Velocity::Unit(i));
      const Velocity back = lagrangian.velocity(t, x, lagrangian.momentum(t, x, v));
      if (!((back - v).norm() <= 1e-6 * (1 + v.norm()))) {
        throw_invalid(where, "lagrangian", "(velocity(t, g, momentum(t, g, v)) = " + format_value(back) +
                                               " for v = " + format_value(v) + " at t = " + format_value(t) + ")",
                      "does not invert its momentum: velocity must be the inverse Legendre map of momentum");
      }
    }
  }
}

}  // namespace cartan::mechanics
