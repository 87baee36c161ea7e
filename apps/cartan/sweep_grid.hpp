#pragma once
// The points of a `cartan sweep`: the base problem with lambda and/or the endpoint replaced
// (the Cartesian product of a lambda list and an endpoint list), or with the keys of each object
// of a --grid JSON file applied. Every point is validated before anything is solved.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "problem_spec.hpp"

namespace cartan::cli {

/// The grid flags of `cartan sweep` as given on the command line (empty: not given).
struct GridFlags {
  std::string lambdas;       ///< "0,0.5,1"
  std::string lambda_range;  ///< "START:STOP:COUNT", COUNT evenly spaced values including both ends
  std::string aT_list;       ///< so3 directions "x,y,z;x,y,z"
  std::string gT_list;       ///< final elements separated by ";", each as --gT (models/catalogue.hpp)
  std::string qT_list;       ///< a manifold's final points separated by ";", each as --qT
  std::string grid_file;     ///< JSON array of objects of problem keys
};

/// One point of the sweep: its validated problem, and what it changes in the base problem.
struct GridPoint {
  ProblemSpec spec;
  nlohmann::json overrides = nlohmann::json::object();  ///< the --grid entry; empty for flag grids
};

/// Limit on the number of points (each keeps one result row in memory).
inline constexpr std::size_t kMaxGridPoints = 1'000'000;

/// The points in table order: for flag grids index = i_lambda * (number of endpoints) + i_endpoint,
/// for a --grid file the file's order. Throws std::invalid_argument ("cartan sweep: ...") for a
/// bad flag or file, no grid flag at all, or a point that does not validate (naming its index).
std::vector<GridPoint> build_grid(const ProblemSpec& base, const GridFlags& flags);

/// The part of a grid one machine solves (`--shard K/M`): the points whose index i has
/// i mod M = K - 1 (interleaved, so that every shard gets points from all over the grid and
/// neighbours in lambda of similar cost are spread out; every point is in exactly one shard).
struct Shard {
  std::size_t k = 1, m = 1;  ///< 1 <= k <= m; 1/1 is the whole grid
  bool contains(std::size_t index) const { return index % m == k - 1; }
  bool whole() const { return m == 1; }
};

/// Parses "K/M" (two integers, 1 <= K <= M <= kMaxGridPoints); throws std::invalid_argument
/// "cartan sweep: --shard = "..." ..." naming the text otherwise.
Shard parse_shard(const std::string& text);

/// Rewrites a message of the shared problem parser ("cartan solve: ...") to start with `where`;
/// a message that already starts with "cartan sweep" is kept, any other gets `where` in front.
std::invalid_argument retitled(const std::invalid_argument& error, const std::string& where);

}  // namespace cartan::cli
