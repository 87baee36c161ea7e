#pragma once
// Forward sweeps of the discrete scheme from (v0, xi0): the shooting map of every solver.

#include <array>
#include <chrono>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cartan/kernels/lie_group/scheme.hpp"
#include "cartan/monitor.hpp"

namespace cartan::transported {

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
struct SweepOutput {
  using Scheme = TransportedScheme<G, L>;
  SchemeNode<G> last;
  std::optional<typename Scheme::NodeTangent> tangent;  ///< filled when tangent columns > 0
  std::vector<groups::CovectorOf<G>>* xi_rates = nullptr;     ///< if set: xi rate of every step (N entries)
  TransportedTrajectory<G>* trajectory = nullptr;     ///< if set: every node (its storage reused)
  std::string failure;                                ///< why the sweep stopped early
  /// If set, polled about every millisecond (SolveMonitor::stop_pending_at): a stop ends the
  /// sweep as a failed one, and the solver's own poll then ends the solve.
  const SolveMonitor* monitor = nullptr;
  /// The work that follows a stop, in sweeps of this kind, projected from this sweep's pace until
  /// the solver has timed a sweep; negative: by kind (sweep_segment).
  double after_stop = -1;
};

/// Runs steps first..last-1 from `node` (node `first`, at t_first) - one segment of a sweep.
/// With `tangent` set, its directions are propagated along. `given_xi` and `out` as in
/// forward_sweep (xi rates are stored at their global step index). Returns false, with
/// `out.failure` set, if the state became non-finite or the inverse Legendre map failed.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
bool sweep_segment(const TransportedScheme<G, L>& scheme, SchemeNode<G> node,
                   std::optional<typename TransportedScheme<G, L>::NodeTangent> tangent, int first, int last,
                   const std::vector<groups::CovectorOf<G>>* given_xi, SweepOutput<G, L>& out) {
  const auto begin = std::chrono::steady_clock::now();
  try {
    // Two nodes (and tangents) used in turn, so that a step writes its result in place of the
    // node before last instead of copying it.
    std::array<SchemeNode<G>, 2> nodes{std::move(node), SchemeNode<G>{}};
    std::array<typename TransportedScheme<G, L>::NodeTangent, 2> tangents;
    if (tangent) tangents[0] = std::move(*tangent);
    if (out.trajectory) {
      out.trajectory->clear();
      out.trajectory->reserve(static_cast<std::size_t>(last - first) + 1);
      out.trajectory->push(nodes[0]);
    }
    std::size_t current = 0;
    // Until a sweep is timed, what follows a stop is projected: out.after_stop (the shooting
    // driver's share), else by kind.
    const double after_stop = out.after_stop >= 0
                                  ? out.after_stop
                                  : SolveMonitor::sweeps_after_stop(out.trajectory != nullptr, tangent.has_value());
    for (int k = first; k < last; ++k) {
      if (SolveMonitor::stop_pending_at(out.monitor, k - first, scheme.problem().N, begin, after_stop)) {
        out.failure = SolveMonitor::stopped_message(k);
        return false;
      }
      const groups::CovectorOf<G>* xi_next = given_xi ? &(*given_xi)[static_cast<std::size_t>(k) + 1] : nullptr;
      const std::size_t next = 1 - current;
      SchemeNode<G>& to = nodes[next];
      const groups::CovectorOf<G> rate =
          tangent ? scheme.step_tangent(nodes[current], tangents[current], to, tangents[next], xi_next)
                  : scheme.step(nodes[current], to, xi_next);
      if (!mechanics::all_finite(to.g) || !mechanics::all_finite(to.mu) || !mechanics::all_finite(to.v) ||
          !mechanics::all_finite(to.xi)) {
        out.failure = "non-finite state at step " + std::to_string(k + 1);
        return false;
      }
      if (out.xi_rates) (*out.xi_rates)[static_cast<std::size_t>(k)] = rate;
      current = next;
      if (out.trajectory) out.trajectory->push(to);
    }
    out.last = std::move(nodes[current]);
    if (tangent) out.tangent = std::move(tangents[current]);
    return true;
  } catch (const ModelError&) {
    throw;  // the model's defect, not a failed iterate
  } catch (const std::exception& e) {
    out.failure = e.what();
    return false;
  }
}

/// Runs the N steps. `given_xi` (N+1 values) selects the paper's mode with a prescribed xi
/// sequence; otherwise xi is integrated forward from xi0. With `tangent_columns` > 0 the
/// tangent-linear map is propagated along (directions: v0, then xi0). Returns false, with
/// `out.failure` set, if the state became non-finite or the inverse Legendre map failed.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
bool forward_sweep(const TransportedScheme<G, L>& scheme, const groups::TangentOf<G>& v0, const groups::CovectorOf<G>& xi0,
                   const std::vector<groups::CovectorOf<G>>* given_xi, int tangent_columns, SweepOutput<G, L>& out) {
  SchemeNode<G> node;
  std::optional<typename TransportedScheme<G, L>::NodeTangent> tangent;
  // Where xi does not feed back (lambda = 0 or 1), only the v0 directions are propagated and the
  // xi0 directions appended at the end: the same Jacobian for half the work.
  constexpr int n = G::kDim;
  const bool decoupled = tangent_columns == 2 * n && given_xi == nullptr && scheme.xi_decoupled();
  try {
    node = scheme.initial(v0, given_xi ? (*given_xi)[0] : xi0);
    if (tangent_columns > 0) tangent = scheme.initial_tangent(node, decoupled ? n : tangent_columns);
  } catch (const ModelError&) {
    throw;  // the model's defect, not a failed iterate
  } catch (const std::exception& e) {
    out.failure = e.what();
    return false;
  }
  const int steps = scheme.problem().N;
  if (out.xi_rates) out.xi_rates->resize(static_cast<std::size_t>(steps));
  if (!sweep_segment(scheme, std::move(node), std::move(tangent), 0, steps, given_xi, out)) return false;
  if (decoupled) TransportedScheme<G, L>::append_decoupled_xi_columns(*out.tangent);
  return true;
}

}  // namespace cartan::transported
