#pragma once
// The one catalogue of the built-in groups and models, the library's (the CLI's `cartan solve`,
// `sweep`, `verify` and the Python module read it): per group its name, how an element is written
// (numbers in JSON and on the command line) and its models, each with its name, Lagrangian type,
// the type's name (the Python class) and default inertia. The first model of a group is its
// default. Everything that depends on the group or model goes through this table: names and
// choices (runtime, ModelInfo), and the typed dispatch (visit_model) that builds a problem for the
// library's solve and verify.
//
// Adding a model: a Lagrangian whose solve is compiled once in the library (its entry in
// CARTAN_TRANSPORTED_BUILTIN_MODELS, kernels/lie_group/compiled.hpp, and src/methods/lie_group/solve_*.cpp),
// its Python class (python/src/bind_<group>.cpp), and one entry in kModels below.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/se2.hpp"
#include "cartan/groups/se3.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"

namespace cartan::models {

/// Input rotation blocks are accepted within this tolerance and projected onto SO(3), so that
/// matrices printed with 7 or more digits can be passed back in; the bottom row of a rigid
/// motion must be [0 .. 0 1] within it and is then set exactly.
inline constexpr double kElementTolerance = 1e-6;

// ---- Groups: how an element is written --------------------------------------------------------

/// so3: a rotation matrix, 9 numbers row-major (or, in problems, a0/aT directions).
struct SO3Entry {
  using Group = groups::SO3;
  static constexpr std::string_view name = "so3";
  static constexpr std::string_view element_what = "a 3x3 rotation matrix, 9 numbers row-major";
  static constexpr bool directions = true;  ///< gT may be given as a0/aT (the minimal rotation)
};
/// heisenberg: the coordinates (a, b, c).
struct HeisenbergEntry {
  using Group = groups::Heisenberg;
  static constexpr std::string_view name = "heisenberg";
  static constexpr std::string_view element_what = "coordinates a,b,c";
  static constexpr bool directions = false;
};
/// se2: a 3x3 homogeneous matrix [[R, t], [0, 1]], 9 numbers row-major.
struct SE2Entry {
  using Group = groups::SE2;
  static constexpr std::string_view name = "se2";
  static constexpr std::string_view element_what = "a 3x3 homogeneous matrix [[R, t], [0, 0, 1]], 9 numbers row-major";
  static constexpr bool directions = false;
};
/// se3: a 4x4 homogeneous matrix [[R, t], [0, 1]], 16 numbers row-major.
struct SE3Entry {
  using Group = groups::SE3;
  static constexpr std::string_view name = "se3";
  static constexpr std::string_view element_what = "a 4x4 homogeneous matrix [[R, t], [0, 0, 0, 1]], 16 numbers row-major";
  static constexpr bool directions = false;
};

// ---- Models -------------------------------------------------------------------------------------

/// One model: its group's entry (Table), its Lagrangian type (built from the inertia matrix), its
/// name and its default inertia (the diagonal).
template <class TableT, class L>
struct ModelEntry {
  using Table = TableT;
  using Lagrangian = L;
  std::string_view name;
  std::string_view type_name;  ///< the Lagrangian type's name, also its Python class's
  std::vector<double> default_inertia;
};

/// The table, in the order names are listed; a group's first model is its default. se2: (x, y,
/// theta), mass 1 and moment of inertia 1/2 (a unit disc); se3: (rho, omega), mass 1 and so3's
/// default rotational inertia.
inline const std::tuple<ModelEntry<SO3Entry, mechanics::RigidBody>, ModelEntry<SO3Entry, mechanics::SO3Oscillator>,
                        ModelEntry<HeisenbergEntry, mechanics::H3Oscillator>, ModelEntry<SE2Entry, mechanics::SE2FreeBody>,
                        ModelEntry<SE3Entry, mechanics::SE3FreeBody>>
    kModels{{"free-rigid-body", "RigidBody", {2, 3, 4}},
            {"oscillator", "SO3Oscillator", {2, 3, 4}},
            {"oscillator", "H3Oscillator", {1, 1, 1}},
            {"free-body", "SE2FreeBody", {1, 1, 0.5}},
            {"free-body", "SE3FreeBody", {1, 1, 1, 2, 3, 4}}};

// ---- Runtime view of the table ------------------------------------------------------------------

/// One model as data: what the parsers and messages need.
struct ModelInfo {
  std::string_view group, model;
  std::string_view type_name;         ///< the Lagrangian type's (and Python class's) name
  int dim = 0;                        ///< algebra dimension: inertia n or n x n, v0/xi0 n numbers
  std::size_t element_size = 0;       ///< numbers of an element (9, 3, 9, 16)
  std::string_view element_what;
  bool directions = false;
  std::vector<double> default_inertia;  ///< diagonal
  std::vector<double> identity;         ///< the identity element's numbers
  /// Throws std::invalid_argument ("<where>: <name> = <value> <problem>") unless `numbers`
  /// (element_size finite numbers) is an element of the group within kElementTolerance.
  void (*check_element)(const std::vector<double>& numbers, std::string_view where, const std::string& name) = nullptr;
};

/// Every model, in table order.
const std::vector<ModelInfo>& model_infos();

/// The group names ("so3, heisenberg, se2, se3") and a group's model names, for messages and help.
std::string group_names();
std::string model_names(std::string_view group);

/// The model `model` of `group`; an empty `model` is the group's default (its first model).
/// Throws std::invalid_argument ("<where>: group = ... is not one of: ..." or "model = ... is
/// not one of: ... (the models of group ...)") for unknown names.
const ModelInfo& find_model(std::string_view group, std::string_view model, std::string_view where);

// ---- Elements and inertia as numbers ------------------------------------------------------------

/// An element's numbers: a matrix row-major, a vector as it is.
template <class Derived>
std::vector<double> element_numbers(const Eigen::MatrixBase<Derived>& x) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(x.size()));
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) out.push_back(x(i, j));
  }
  return out;
}

/// The group element of checked numbers (ModelInfo::check_element): a matrix read row-major with
/// its rotation block projected onto SO(3) and its bottom row set exactly; coordinates as they are.
template <groups::LieGroup G>
groups::ElementOf<G> element_of(const std::vector<double>& numbers);

/// An n x n matrix written as n numbers (its diagonal) or n^2 (the matrix, row-major): an inertia,
/// a mass, a metric. Sizes are checked by the CLI (validate, read_result: apps/cartan/problem_spec.hpp),
/// the api and Python; the library's model checks symmetry, finiteness and definiteness when it is
/// built.
Eigen::MatrixXd square_matrix(const std::vector<double>& numbers, Eigen::Index n);

/// The inertia as a matrix (square_matrix).
template <int n>
Eigen::Matrix<double, n, n> inertia_matrix(const std::vector<double>& numbers) {
  return square_matrix(numbers, n);
}

/// Rethrows the library's rejection `error` of the inertia `matrix` (given as `numbers`) as
/// "<where>: inertia = <excerpt of the numbers> <the library's reason>".
[[noreturn]] void rethrow_inertia(const std::invalid_argument& error, const Eigen::Ref<const Eigen::MatrixXd>& matrix,
                                  const std::vector<double>& numbers, std::string_view where);

/// Builds the model's Lagrangian from the inertia numbers (inertia_matrix), so that the library
/// validates the inertia: asymmetric (beyond relative 1e-12), non-finite or not positive-definite
/// matrices throw std::invalid_argument "<where>: inertia = <excerpt> <the library's reason>".
template <class Entry>
typename Entry::Lagrangian make_lagrangian(const std::vector<double>& inertia, std::string_view where) {
  const auto matrix = inertia_matrix<Entry::Table::Group::kDim>(inertia);
  try {
    return typename Entry::Lagrangian(matrix);
  } catch (const std::invalid_argument& e) {
    rethrow_inertia(e, matrix, inertia, where);
  }
}

/// Throws the model's inertia rejection for `inertia` (n or n^2 numbers) as make_lagrangian does.
void check_inertia(const ModelInfo& model, const std::vector<double>& inertia, std::string_view where);

// ---- Typed dispatch ----------------------------------------------------------------------------

/// Calls visit(entry) for the ModelEntry of (group, model) in kModels and returns its result
/// (the same type for every entry); Entry::Table::Group and Entry::Lagrangian are its types.
/// Unknown names throw as find_model does.
template <class Visitor>
auto visit_model(std::string_view group, std::string_view model, std::string_view where, Visitor&& visit) {
  const ModelInfo& info = find_model(group, model, where);
  return std::apply(
      [&](const auto&... entries) {
        std::optional<decltype(visit(std::get<0>(kModels)))> out;
        (void)((std::decay_t<decltype(entries)>::Table::name == info.group && entries.name == info.model
                    ? (out.emplace(visit(entries)), true)
                    : false) ||
               ...);
        return std::move(*out);
      },
      kModels);
}

}  // namespace cartan::models
