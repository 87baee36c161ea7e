#pragma once
// Forward sweeps of the discrete scheme from (v0, xi0): the shooting map of every solver.

#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cartan/transported/scheme.hpp"

namespace cartan::transported {

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
struct SweepOutput {
  using Scheme = TransportedScheme<G, L>;
  SchemeNode<G> last;
  std::optional<typename Scheme::NodeTangent> tangent;  ///< filled when tangent columns > 0
  std::vector<groups::CovectorOf<G>>* xi_rates = nullptr;     ///< if set: xi rate of every step (N entries)
  TransportedTrajectory<G>* trajectory = nullptr;     ///< if set: every node
  std::string failure;                                ///< why the sweep stopped early
};

/// Runs steps first..last-1 from `node` (node `first`, at t_first) - one segment of a sweep.
/// With `tangent` set, its directions are propagated along. `given_xi` and `out` as in
/// forward_sweep (xi rates are stored at their global step index). Returns false, with
/// `out.failure` set, if the state became non-finite or the inverse Legendre map failed.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
bool sweep_segment(const TransportedScheme<G, L>& scheme, SchemeNode<G> node,
                   std::optional<typename TransportedScheme<G, L>::NodeTangent> tangent, int first, int last,
                   const std::vector<groups::CovectorOf<G>>* given_xi, SweepOutput<G, L>& out) {
  try {
    SchemeNode<G> next;
    typename TransportedScheme<G, L>::NodeTangent dnext;
    if (out.trajectory) {
      *out.trajectory = {};
      out.trajectory->reserve(static_cast<std::size_t>(last - first) + 1);
      out.trajectory->push(node);
    }
    for (int k = first; k < last; ++k) {
      const groups::CovectorOf<G>* xi_next = given_xi ? &(*given_xi)[static_cast<std::size_t>(k) + 1] : nullptr;
      groups::CovectorOf<G> rate;
      if (tangent) {
        rate = scheme.step_tangent(node, *tangent, next, dnext, xi_next);
        std::swap(*tangent, dnext);
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
    out.tangent = std::move(tangent);
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
  try {
    node = scheme.initial(v0, given_xi ? (*given_xi)[0] : xi0);
    if (tangent_columns > 0) tangent = scheme.initial_tangent(node, tangent_columns);
  } catch (const ModelError&) {
    throw;  // the model's defect, not a failed iterate
  } catch (const std::exception& e) {
    out.failure = e.what();
    return false;
  }
  const int steps = scheme.problem().N;
  if (out.xi_rates) out.xi_rates->resize(static_cast<std::size_t>(steps));
  return sweep_segment(scheme, std::move(node), std::move(tangent), 0, steps, given_xi, out);
}

}  // namespace cartan::transported
