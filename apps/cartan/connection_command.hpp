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
#include "cartan/models/catalogue.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

/// The connection of a validated spec on the group G: levi-civita of spec.metric, or the bilinear
/// map of spec.alpha_values (alpha(e_i, e_j) = sum_k alpha[i][j][k] e_k).
template <groups::LieGroup G>
manifolds::GroupManifold<G> connection_manifold(const ProblemSpec& spec) {
  if (connection_kind(spec) == connections::ConnectionKind::LeviCivita) {
    return manifolds::GroupManifold<G>::levi_civita(models::inertia_matrix<G::kDim>(spec.metric));
  }
  return manifolds::GroupManifold<G>::coefficients(spec.alpha_values);
}

/// The general problem of a validated group spec with a connection other than cartan-schouten,
/// for the model table's Entry (models::visit_model): the model behind the erased Lagrangian, whose solve
/// and verify the library compiles once (general/compiled.hpp).
template <class Entry>
general::ErasedProblem<manifolds::GroupManifold<typename Entry::Table::Group>> connection_problem(
    const ProblemSpec& spec, std::string_view where) {
  using G = typename Entry::Table::Group;
  using M = manifolds::GroupManifold<G>;
  using L = general::OnGroupManifold<G, typename Entry::Lagrangian>;
  return {connection_manifold<G>(spec), general::ErasedLagrangian<M>(L{models::make_lagrangian<Entry>(spec.inertia, where)}),
          spec.T, spec.N, models::element_of<G>(spec.g0), models::element_of<G>(final_element(spec)), std::nullopt};
}

/// Solves a validated group problem whose connection is not cartan-schouten.
nlohmann::json solve_with_connection(const ProblemSpec& spec, const SolveMonitor& monitor);

}  // namespace cartan::cli
