#pragma once
// `cartan solve --group G --connection levi-civita|coefficients`: a model of the table under a
// left-invariant connection other than Cartan–Schouten, solved by the general solver
// (include/cartan/general/solve.hpp on manifolds::GroupManifold<G>, the model through
// general::OnGroupManifold). The result has the keys of a group result, with `Xi` (n^2 numbers a
// row, row-major) in place of `xi`, and `connection`, `metric` (levi-civita) or `alpha`
// (coefficients, as the nested array) echoed.

#include <nlohmann/json.hpp>

#include "cartan/general/erased_lagrangian.hpp"
#include "cartan/monitor.hpp"
#include "model_table.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

/// The connection of a validated spec on the group G: levi-civita of spec.metric, or the bilinear
/// map of spec.alpha_values (alpha(e_i, e_j) = sum_k alpha[i][j][k] e_k).
template <groups::LieGroup G>
manifolds::GroupManifold<G> connection_manifold(const ProblemSpec& spec) {
  constexpr int n = G::kDim;
  if (spec.connection == "levi-civita") return manifolds::GroupManifold<G>::levi_civita(inertia_matrix<n>(spec.metric));
  typename connections::InvariantConnection<G>::Coefficients c;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) c[i](k, j) = spec.alpha_values[static_cast<std::size_t>((i * n + j) * n + k)];
    }
  }
  return manifolds::GroupManifold<G>(connections::InvariantConnection<G>(groups::Side::Left, c));
}

/// The general problem of a validated group spec with a connection other than cartan-schouten,
/// for the model table's Entry (visit_model): the model behind the erased Lagrangian, whose solve
/// and verify the library compiles once (general/compiled.hpp).
template <class Entry>
general::ErasedProblem<manifolds::GroupManifold<typename Entry::Table::Group>> connection_problem(
    const ProblemSpec& spec, std::string_view where) {
  using G = typename Entry::Table::Group;
  using M = manifolds::GroupManifold<G>;
  using L = general::OnGroupManifold<G, typename Entry::Lagrangian>;
  return {connection_manifold<G>(spec), general::ErasedLagrangian<M>(L{make_lagrangian<Entry>(spec.inertia, where)}),
          spec.T, spec.N, element_of<G>(spec.g0), element_of<G>(final_element(spec)), std::nullopt};
}

/// Solves a validated group problem whose connection is not cartan-schouten.
nlohmann::json solve_with_connection(const ProblemSpec& spec, const SolveMonitor& monitor);

}  // namespace cartan::cli
