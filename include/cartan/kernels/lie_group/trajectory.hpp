#pragma once
// The transported problem's state at a node and its discrete trajectory (nodes k = 0..N, or the
// samples of a continuous solution): what the scheme (scheme.hpp) produces, the solvers return
// (solution.hpp) and the verifier reads (kernels/lie_group/verify.hpp).

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/principle/horizon.hpp"
#include "cartan/principle/samples.hpp"

namespace cartan::transported {

template <groups::LieGroup G>
struct SchemeNode {
  double t = 0;
  groups::ElementOf<G> g;
  groups::ElementOf<G> transport;  ///< h_k with P_k = Ad(h_k)
  groups::CovectorOf<G> mu;
  groups::CovectorOf<G> xi;
  groups::TangentOf<G> v;
};

/// The discrete trajectory at every node k = 0..N.
template <groups::LieGroup G>
struct TransportedTrajectory {
  std::vector<double> t;
  std::vector<groups::ElementOf<G>> g;
  std::vector<groups::TangentOf<G>> v;
  std::vector<groups::CovectorOf<G>> mu;
  std::vector<groups::CovectorOf<G>> xi;

  /// Empties the trajectory and keeps its storage (a sweep that records reuses it).
  void clear() { t.clear(), g.clear(), v.clear(), mu.clear(), xi.clear(); }
  void reserve(std::size_t n) {
    t.reserve(n), g.reserve(n), v.reserve(n), mu.reserve(n), xi.reserve(n);
  }
  void push(const SchemeNode<G>& node) {
    t.push_back(node.t), g.push_back(node.g), v.push_back(node.v), mu.push_back(node.mu), xi.push_back(node.xi);
  }

  /// Throws std::invalid_argument (the one check of samples, principle/samples.hpp: "<where>:
  /// trajectory... = <value> <problem>") unless there are at least 2 samples with g, v and xi (and
  /// mu when `with_mu`) at every time, all finite, and the times increase strictly from 0 to T (to
  /// `time_tolerance` T).
  void validate(double T, std::string_view where, bool with_mu, double time_tolerance) const {
    const SampleRules rules{.time_tolerance = time_tolerance};
    if (with_mu) {
      require_samples(t, T, {sample_column("g", g), sample_column("v", v), sample_column("mu", mu), sample_column("xi", xi)},
                      rules, where, "trajectory");
    } else {
      require_samples(t, T, {sample_column("g", g), sample_column("v", v), sample_column("xi", xi)}, rules, where,
                      "trajectory");
    }
  }
};

}  // namespace cartan::transported
