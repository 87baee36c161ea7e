#pragma once
// The checks every problem and every verification share, written once: the horizon [0, T] in N
// steps and the tolerance asked for. Messages "<where>: <name> = <value> <problem>".

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/errors.hpp"

namespace cartan {

/// Throws std::invalid_argument naming N when N steps cannot fit in this machine's physical
/// memory at kBytesPerStepAtLeast each (a lower bound of every kernel's trajectory and work: a
/// problem refused here could never be solved; N = 2^31 - 1 from Python grew to gigabytes before).
void require_steps_fit(int N, std::string_view where);
inline constexpr double kBytesPerStepAtLeast = 1024;

/// Throws std::invalid_argument unless T is positive and finite, N >= 1 and N steps fit in memory.
inline void require_horizon(double T, int N, std::string_view where) {
  require_finite(T, where, "T");
  if (!(T > 0)) throw_invalid(where, "T", format_value(T), "must be positive");
  if (N < 1) throw_invalid(where, "N", std::to_string(N), "must be at least 1");
  require_steps_fit(N, where);
}

/// The time of the node after the one at t on the horizon [0, T] with steps h = T / N: t + h, and
/// T itself for the last node (the sum of N steps of T / N misses T by rounding, e.g.
/// 0.9999999999999897 for T = 1, N = 300, and a result's last time must be its T: dense output
/// and verification take [0, T]).
inline double next_node_time(double t, double h, double T) {
  const double next = t + h;
  return std::abs(next - T) < h / 2 ? T : next;
}

/// Throws std::invalid_argument "<where>: <what>.t..." unless the sample times t strictly increase
/// and run from 0 to T within tolerance * T at both ends: what every check of a sampled solution
/// assumes of its times (a guess, a trajectory to verify, the quantities along one).
inline void require_sample_times(const std::vector<double>& t, double T, double tolerance, std::string_view where,
                                 std::string_view what) {
  const std::string name = std::string(what).append(".t");
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (!(t[k] > t[k - 1])) {
      throw_invalid(where, std::string(name).append("[").append(std::to_string(k)).append("]"), format_value(t[k]),
                    std::string("must be greater than the time before it, ")
                        .append(format_value(t[k - 1]))
                        .append(" (times must be strictly increasing)"));
    }
  }
  if (t.empty() || !(std::abs(t.front()) <= tolerance * T) || !(std::abs(t.back() - T) <= tolerance * T)) {
    // Appended, not "[" + std::string: GCC 12's -Wrestrict misreads that pattern once inlined.
    const std::string span = t.empty() ? std::string("(empty)")
                                       : std::string("[").append(format_value(t.front())).append(", ")
                                             .append(format_value(t.back())).append("]");
    throw_invalid(where, name, span, std::string("must run from 0 to T = ").append(format_value(T)));
  }
}

/// Throws std::invalid_argument unless tol is positive and finite.
inline void require_tolerance(double tol, std::string_view where) {
  if (!(tol > 0) || !std::isfinite(tol)) throw_invalid(where, "tol", format_value(tol), "must be positive and finite");
}

}  // namespace cartan
