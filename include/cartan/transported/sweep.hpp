#pragma once
// Forward sweeps of the discrete scheme from (v0, xi0): the shooting map of every solver.

#include <exception>
#include <optional>
#include <string>

#include "cartan/transported/scheme.hpp"

namespace cartan {

template <LieGroup G, ReducedLagrangian<G> L>
struct SweepOutput {
  using Scheme = TransportedScheme<G, L>;
  SchemeNode<G> last;
  std::optional<typename Scheme::NodeTangent> tangent;  ///< filled when tangent columns > 0
  std::vector<CovectorOf<G>>* xi_rates = nullptr;     ///< if set: xi rate of every step (N entries)
  TransportedTrajectory<G>* trajectory = nullptr;     ///< if set: every node
  std::string failure;                                ///< why the sweep stopped early
};

/// Runs the N steps. `given_xi` (N+1 values) selects the paper's mode with a prescribed xi
/// sequence; otherwise xi is integrated forward from xi0. With `tangent_columns` > 0 the
/// tangent-linear map is propagated along (directions: v0, then xi0). Returns false, with
/// `out.failure` set, if the state became non-finite or the inverse Legendre map failed.
template <LieGroup G, ReducedLagrangian<G> L>
bool forward_sweep(const TransportedScheme<G, L>& scheme, const TangentOf<G>& v0, const CovectorOf<G>& xi0,
                   const std::vector<CovectorOf<G>>* given_xi, int tangent_columns, SweepOutput<G, L>& out) {
  using Scheme = TransportedScheme<G, L>;
  const int steps = scheme.problem().N;
  try {
    SchemeNode<G> node = scheme.initial(v0, given_xi ? (*given_xi)[0] : xi0);
    SchemeNode<G> next;
    typename Scheme::NodeTangent d, dnext;
    if (tangent_columns > 0) d = scheme.initial_tangent(node, tangent_columns);
    if (out.trajectory) {
      *out.trajectory = {};
      out.trajectory->reserve(static_cast<std::size_t>(steps) + 1);
      out.trajectory->push(node);
    }
    if (out.xi_rates) out.xi_rates->resize(static_cast<std::size_t>(steps));
    for (int k = 0; k < steps; ++k) {
      const CovectorOf<G>* xi_next = given_xi ? &(*given_xi)[static_cast<std::size_t>(k) + 1] : nullptr;
      CovectorOf<G> rate;
      if (tangent_columns > 0) {
        rate = scheme.step_tangent(node, d, next, dnext, xi_next);
        std::swap(d, dnext);
      } else {
        rate = scheme.step(node, next, xi_next);
      }
      if (!next.g.allFinite() || !next.mu.allFinite() || !next.v.allFinite() || !next.xi.allFinite()) {
        out.failure = "non-finite state at step " + std::to_string(k + 1);
        return false;
      }
      if (out.xi_rates) (*out.xi_rates)[static_cast<std::size_t>(k)] = rate;
      node = next;
      if (out.trajectory) out.trajectory->push(node);
    }
    out.last = node;
    if (tangent_columns > 0) out.tangent = std::move(d);
    return true;
  } catch (const std::exception& e) {
    out.failure = e.what();
    return false;
  }
}

}  // namespace cartan
