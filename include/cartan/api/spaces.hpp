#pragma once
// The one catalogue of the spaces the library compiles a solve for (layer "api"): per space its
// name, its dimensions, how a point is written, its connections (the first is its default) and
// whether the particle's uniform gravity applies. The api's ManifoldProblem (solve.hpp), the result
// file (result_file.hpp), the CLI's --manifold and its help, and Python's cartan.SPACES read it;
// the models of a group (the paper's systems) are models/catalogue.hpp's. Compiled once in
// the library cartan_io (src/api/spaces.cpp), which cartan_api links.
//
// Adding a space: its type's solve compiled (kernels/manifold/compiled.hpp, src/methods/solve_<space>.cpp),
// its entry here, and its branch in src/api/problems.cpp (how its points and connection are read).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/connections/connection_kind.hpp"

namespace cartan::api {

/// The prefix of the name of what a user defined in Python ("python:<name>"): a Lagrangian (a
/// result file's model) or a Chart (its manifold). A file records the name, not the code: read,
/// never rebuilt, solved or verified here.
inline constexpr std::string_view kPythonPrefix = "python:";

/// How a space's points and connection are given.
enum class SpaceKind {
  Group,      ///< a Lie group of models/catalogue.hpp: an element's numbers; a left-invariant connection
  Quadric,    ///< a quadric of R^3 (x, y, z moved onto it) with the Levi-Civita connection of its metric
  Euclidean,  ///< R^n: n coordinates; constant Christoffel symbols (coefficients), 0 by default
};

/// One space as data.
struct SpaceInfo {
  std::string_view name;
  SpaceKind kind;
  std::vector<int> dims;                                    ///< the dimensions compiled (m: v, mu are m numbers)
  std::string_view point_what;                              ///< how a point is written
  std::vector<connections::ConnectionKind> connections;     ///< those it takes; the first is its default
  bool gravity = false;                                     ///< V = G q[last] applies (points are vectors of R^d)
  std::string_view what;                                    ///< one line for help and docs
};

/// Every space, in the order names are listed: the groups of models/catalogue.hpp, the sphere, the
/// hyperbolic plane, Euclidean space.
const std::vector<SpaceInfo>& spaces();

/// "so3, heisenberg, se2, se3, sphere, hyperbolic-plane, euclidean": for messages and help.
std::string space_names();

/// The space named `name`. Throws std::invalid_argument "<where>: manifold = <name> is not one
/// of: <space_names()>" for any other name (and says so of a space defined in Python).
const SpaceInfo& find_space(std::string_view name, std::string_view where);

/// The dimension of R^n or of a chart, which its points' coordinates give: the length of q0, one
/// of euclidean's compiled dims (2 or 3). Throws std::invalid_argument "<where>: q0 = ... must
/// have 2 or 3 numbers ..." naming `space` otherwise.
std::size_t coordinate_count(std::string_view space, const std::vector<double>& q0, std::string_view where);

/// Throws std::invalid_argument "<where>: connection = <word> is not a connection of <space> (it
/// takes: ...)" unless `space` takes `connection`.
void require_connection(const SpaceInfo& space, connections::ConnectionKind connection, std::string_view where);

}  // namespace cartan::api
