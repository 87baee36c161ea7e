#pragma once
// Reading a `cartan solve` result file back (for `cartan verify`): every key the checks need is
// validated here, at the edge (DESIGN.md), so the checks may assume a well-formed trajectory.
// No I/O: the caller parses the file (json_io.hpp); a fuzz target calls read_result directly.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

namespace cartan::cli {

/// A validated result: the problem (group, model, inertia, lambda, T, g0, gT, tol), how it was
/// solved (method, order, N, status) and the sampled trajectory, one row per time.
struct ResultFile {
  std::string status, group, model, method;
  double lambda = 0, T = 0, tol = 0;
  int N = 0, order = 0;
  Eigen::Vector3d inertia;     ///< diagonal, entries > 0
  Eigen::VectorXd g0, gT;      ///< so3: 9 numbers row-major (orthogonal within 1e-6); heisenberg: a,b,c
  Eigen::VectorXd t;           ///< M >= 2 strictly increasing times, t[0] = 0, t[M-1] = T
  Eigen::MatrixXd g, v, mu, xi;  ///< M rows; g has 9 (so3) or 3 (heisenberg) columns, the others 3
};

/// Orthogonality tolerance of the rotations in a result file (the CLI's input tolerance).
inline constexpr double kResultRotationTolerance = 1e-6;

/// Validates `j` and returns its contents. Throws std::invalid_argument ("cartan verify: <key> =
/// <value> <problem>", with the row index for trajectory rows) at the first bad value, and no
/// other exception.
ResultFile read_result(const nlohmann::json& j);

}  // namespace cartan::cli
