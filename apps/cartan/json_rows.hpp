#pragma once
// Trajectories as JSON rows, the CLI contract's layout: an SO(3) element as 9 numbers row-major,
// a 3-vector (a Heisenberg element, v, mu, xi) as 3 numbers.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <vector>

namespace cartan::cli {

inline nlohmann::json row_major(const Eigen::Matrix3d& m) {
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2)};
}

inline nlohmann::json rows(const std::vector<Eigen::Matrix3d>& g) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& m : g) out.push_back(row_major(m));
  return out;
}

template <class Vec>
nlohmann::json rows(const std::vector<Vec>& x) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : x) out.push_back({v[0], v[1], v[2]});
  return out;
}

}  // namespace cartan::cli
