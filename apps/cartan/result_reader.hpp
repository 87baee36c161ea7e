#pragma once
// Reading a `cartan solve` result file back (for `cartan verify`): every key the checks need is
// validated here, at the edge (DESIGN.md), so the checks may assume a well-formed trajectory.
// No I/O: the caller parses the file (json_io.hpp); a fuzz target calls read_result directly.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

#include "problem_spec.hpp"

namespace cartan::cli {

/// A validated result: the problem (the echoed fields of problem_fields(): group, model,
/// inertia, lambda, T, N, tol, g0, and gT), how it was solved (method, order, status) and the
/// sampled trajectory, one row per time.
struct ResultFile {
  std::string status, method;
  /// Groups: group, model, inertia (n or n^2 numbers), lambda, T, N, tol, g0, gT, connection
  /// (metric, alpha_values); --manifold: manifold, model, mass, gravity, q0, qT, T, N, tol.
  ProblemSpec problem;
  int order = 0;
  Eigen::VectorXd t;           ///< M >= 2 strictly increasing times, t[0] = 0, t[M-1] = T
  /// M rows: g has the element's numbers (models/catalogue.hpp; a manifold: q, 3 numbers), v and mu n,
  /// xi n (Cartan–Schouten) or Xi n^2 (the general solver: a manifold or another connection).
  Eigen::MatrixXd g, v, mu, xi, Xi;

  bool general() const { return is_manifold_problem(problem) || is_general_connection(problem); }
};

/// Validates `j` and returns its contents. Throws std::invalid_argument ("cartan verify: <key> =
/// <value> <problem>", with the row index for trajectory rows) at the first bad value, and no
/// other exception.
ResultFile read_result(const nlohmann::json& j);

}  // namespace cartan::cli
