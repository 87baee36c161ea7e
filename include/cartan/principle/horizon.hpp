#pragma once
// The checks every problem and every verification share, written once: the horizon [0, T] in N
// steps and the tolerance asked for. Messages "<where>: <name> = <value> <problem>".

#include <string>
#include <string_view>

#include "cartan/errors.hpp"

namespace cartan {

/// Throws std::invalid_argument unless T is positive and finite and N >= 1.
inline void require_horizon(double T, int N, std::string_view where) {
  require_finite(T, where, "T");
  if (!(T > 0)) throw_invalid(where, "T", format_value(T), "must be positive");
  if (N < 1) throw_invalid(where, "N", std::to_string(N), "must be at least 1");
}

/// Throws std::invalid_argument unless tol is positive and finite.
inline void require_tolerance(double tol, std::string_view where) {
  if (!(tol > 0) || !std::isfinite(tol)) throw_invalid(where, "tol", format_value(tol), "must be positive and finite");
}

}  // namespace cartan
