// The catalogue of spaces (cartan/api/spaces.hpp): the groups from models/catalogue.hpp, then the
// quadrics and Euclidean space.
#include "cartan/api/spaces.hpp"

#include "cartan/errors.hpp"
#include "cartan/models/catalogue.hpp"

namespace cartan::api {

namespace {

using connections::ConnectionKind;

std::vector<SpaceInfo> make_spaces() {
  std::vector<SpaceInfo> out;
  for (const models::ModelInfo& m : models::model_infos()) {
    if (!out.empty() && out.back().name == m.group) continue;  // once per group
    out.push_back({m.group, SpaceKind::Group, {m.dim}, m.element_what,
                   {ConnectionKind::CartanSchouten, ConnectionKind::LeviCivita, ConnectionKind::Coefficients}, false,
                   "a Lie group with a left-invariant connection (lambda, metric or alpha)"});
  }
  out.push_back({"sphere", SpaceKind::Quadric, {2}, "x,y,z (divided by its length)", {ConnectionKind::LeviCivita}, true,
                 "the unit sphere S^2 in R^3 with its Levi-Civita connection"});
  out.push_back({"hyperbolic-plane", SpaceKind::Quadric, {2},
                 "x,y,z with z > 0 and z^2 > x^2 + y^2 (moved onto z^2 - x^2 - y^2 = 1)", {ConnectionKind::LeviCivita}, true,
                 "the hyperbolic plane H^2 (hyperboloid model) with its Levi-Civita connection"});
  out.push_back({"euclidean", SpaceKind::Euclidean, {2, 3}, "n coordinates (n = 2 or 3)",
                 {ConnectionKind::LeviCivita, ConnectionKind::Coefficients}, true,
                 "R^2 or R^3: the flat connection (levi-civita) or constant Christoffel symbols (coefficients, "
                 "alpha[i][j][k] = Gamma^k_ij)"});
  return out;
}

std::string joined(const std::vector<std::string_view>& words) {
  std::string out;
  for (const auto& w : words) out.append(out.empty() ? "" : ", ").append(w);
  return out;
}

}  // namespace

const std::vector<SpaceInfo>& spaces() {
  static const std::vector<SpaceInfo> all = make_spaces();
  return all;
}

std::string space_names() {
  std::vector<std::string_view> names;
  for (const auto& s : spaces()) names.push_back(s.name);
  return joined(names);
}

const SpaceInfo& find_space(std::string_view name, std::string_view where) {
  for (const auto& s : spaces()) {
    if (s.name == name) return s;
  }
  if (name.starts_with(kPythonPrefix)) {
    throw_invalid(where, "manifold", quote_input(name),
                  "is a space defined in Python (a Chart), which a file only names: it is solved and verified in Python");
  }
  throw_invalid(where, "manifold", quote_input(name), "is not one of: " + space_names());
}

std::size_t coordinate_count(std::string_view space, const std::vector<double>& q0, std::string_view where) {
  const std::vector<int>& dims = find_space("euclidean", where).dims;
  for (const int n : dims) {
    if (q0.size() == static_cast<std::size_t>(n)) return q0.size();
  }
  throw_invalid(where, "q0", excerpt(q0),
                "must have 2 or 3 numbers (the coordinates of a point of " + std::string(space) + ": R^2 or R^3, or a chart of them)");
}

void require_connection(const SpaceInfo& space, connections::ConnectionKind connection, std::string_view where) {
  std::vector<std::string_view> takes;
  for (const auto c : space.connections) {
    if (c == connection) return;
    takes.push_back(to_string(c));
  }
  throw_invalid(where, "connection", std::string(to_string(connection)),
                "is not a connection of " + std::string(space.name) + " (it takes: " + joined(takes) + ")");
}

}  // namespace cartan::api
