#pragma once
// What the api's solve and verify (solve.cpp, verify.cpp) share: a GroupProblem or ManifoldProblem
// checked and turned into the problem a compiled solver takes.
// Private to src/api/.

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/api/solve.hpp"
#include "cartan/api/spaces.hpp"
#include "cartan/errors.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/models/catalogue.hpp"
#include "samples.hpp"

namespace cartan::api::detail {

/// A group problem's numbers once checked: the model's entry, the inertia (the model's default
/// when none was given) and g0 (the identity when none was given).
struct CheckedGroupProblem {
  const models::ModelInfo* model = nullptr;
  std::vector<double> inertia, g0;
};
/// api::check of the problem and guess, then (with `elements`) that g0 and gT are elements of the
/// group (ModelInfo::check_element).
CheckedGroupProblem checked(const GroupProblem& problem, const Guess& guess, bool elements, std::string_view where);

/// The manifold problem checked (api::check) as the general problem on M (the particle with the
/// problem's connection, its points moved onto M, its frame at q0 when it has one): instantiated in
/// problems.cpp for the spaces of spaces.hpp.
template <class M>
general::ErasedProblem<M> manifold_problem(const ManifoldProblem& problem, const Guess& guess, std::string_view where);

/// visit(the general problem of `problem` on its space), checked; a name not in spaces() refused by name.
template <class Visitor>
auto visit_manifold(const ManifoldProblem& problem, const Guess& guess, std::string_view where, Visitor&& visit) {
  const SpaceInfo& space = find_space(problem.manifold, where);
  switch (space.kind) {
    case SpaceKind::Group:
      return models::visit_model(space.name, {}, where, [&]<class Entry>(const Entry&) {
        return visit(manifold_problem<manifolds::GroupManifold<typename Entry::Table::Group>>(problem, guess, where));
      });
    case SpaceKind::Quadric:
      if (space.name == manifolds::Sphere::name()) return visit(manifold_problem<manifolds::Sphere>(problem, guess, where));
      return visit(manifold_problem<manifolds::HyperbolicPlane>(problem, guess, where));
    case SpaceKind::Euclidean:
      if (coordinate_count(space.name, problem.q0, where) == 2) {
        return visit(manifold_problem<manifolds::Euclidean<2>>(problem, guess, where));
      }
      return visit(manifold_problem<manifolds::Euclidean<3>>(problem, guess, where));
  }
  throw std::logic_error("visit_manifold: unknown kind of space");
}

/// The connection of a checked non-Cartan–Schouten group problem on G: Levi-Civita of the metric
/// (the inertia when none is given), or the bilinear map alpha.
template <groups::LieGroup G>
manifolds::GroupManifold<G> group_manifold(const GroupProblem& problem, const CheckedGroupProblem& checked) {
  if (problem.connection == connections::ConnectionKind::LeviCivita) {
    return manifolds::GroupManifold<G>::levi_civita(
        models::inertia_matrix<G::kDim>(problem.metric.empty() ? checked.inertia : problem.metric));
  }
  return manifolds::GroupManifold<G>::coefficients(problem.alpha);
}

/// The general problem of a checked group problem for the catalogue's Entry: the model behind the
/// erased Lagrangian on GroupManifold<G> (kernels/manifold/compiled.hpp), with the given boundary elements.
template <class Entry>
general::ErasedProblem<manifolds::GroupManifold<typename Entry::Table::Group>> connection_problem(
    const GroupProblem& problem, const CheckedGroupProblem& checked, const groups::ElementOf<typename Entry::Table::Group>& g0,
    const groups::ElementOf<typename Entry::Table::Group>& gT, std::string_view where) {
  using G = typename Entry::Table::Group;
  using M = manifolds::GroupManifold<G>;
  using L = general::OnGroupManifold<G, typename Entry::Lagrangian>;
  return {group_manifold<G>(problem, checked), general::ErasedLagrangian<M>(L{models::make_lagrangian<Entry>(checked.inertia, where)}),
          problem.T, problem.N, g0, gT, std::nullopt};
}

}  // namespace cartan::api::detail
