#pragma once
// The Lie-group kernel's guesses (typed: a v0 and a xi0 of the group, or a trajectory), and the
// vocabulary's options in its namespace (principle/options.hpp defines them).

#include <optional>
#include <stdexcept>
#include <string_view>

#include "cartan/errors.hpp"
#include "cartan/kernels/lie_group/method.hpp"
#include "cartan/kernels/lie_group/trajectory.hpp"
#include "cartan/principle/options.hpp"

namespace cartan::transported {

using ::cartan::apply_time_limit;
using ::cartan::ContinuationOptions;
using ::cartan::SchemeOrder;
using ::cartan::ShootingOptions;
using ::cartan::SolveOptions;
using ::cartan::timed;
using ::cartan::with_deadline;
namespace detail {
using ::cartan::path_shooting;
using ::cartan::seconds_since;
}  // namespace detail

/// Optional starting points: v0 and xi0, or a whole trajectory (t from 0 to T, g, v and xi at
/// every entry; mu is not read). A trajectory supplies v0 and xi0 to the shooting methods and
/// the whole guess to collocation.
template <groups::LieGroup G>
struct SolveGuess {
  std::optional<groups::TangentOf<G>> v0;
  std::optional<groups::CovectorOf<G>> xi0;
  std::optional<TransportedTrajectory<G>> trajectory;

  bool empty() const { return !v0 && !xi0 && !trajectory; }
  /// The guess of v(0) and of xi(0): given directly, or the trajectory's first entry; none if neither.
  std::optional<groups::TangentOf<G>> start_v0() const { return v0 ? v0 : trajectory ? std::optional(trajectory->v.front()) : std::nullopt; }
  std::optional<groups::CovectorOf<G>> start_xi0() const {
    return xi0 ? xi0 : trajectory ? std::optional(trajectory->xi.front()) : std::nullopt;
  }

  /// Throws std::invalid_argument for non-finite values, both v0/xi0 and a trajectory, or a
  /// trajectory that is not on [0, T] with strictly increasing times and rows of equal count.
  void validate(double T) const {
    constexpr std::string_view where = "SolveGuess";
    if (v0) require_finite(*v0, where, "v0");
    if (xi0) require_finite(*xi0, where, "xi0");
    if (!trajectory) return;
    if (v0 || xi0) throw std::invalid_argument("SolveGuess: give v0/xi0 or a trajectory, not both");
    trajectory->validate(T, where, false, 1e-12);
  }
};

}  // namespace cartan::transported
