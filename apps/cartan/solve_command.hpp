#pragma once
// `cartan solve`: a validated ProblemSpec translated into the library's problem description
// (cartan/api/solve.hpp), solved by the library, which decides what runs, and its Result as the
// JSON of the CLI contract (docs/reference.md). Nothing here names a solver, a group type or a model type.

#include <nlohmann/json.hpp>

#include "cartan/api/solve.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/monitor.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

/// The boundary data of a validated so3 spec: g0 and gT as rotations (the 9 numbers projected
/// onto SO(3), models::element_of in models/catalogue.hpp), gT the minimal rotation taking a0 to aT when those
/// are given. Cheap; throws std::invalid_argument naming g0/gT when a matrix is not a rotation.
struct SO3Endpoints {
  groups::SO3::Element g0, gT;
};
SO3Endpoints so3_endpoints(const ProblemSpec& spec);

/// The library's SolveOptions of a validated spec (method, continuation, order, tol, ...).
cartan::SolveOptions solve_options(const ProblemSpec& spec);

/// Solves a validated spec with the library's api::solve. The JSON (result_json) has status,
/// message, the echoed problem, method, order, branch, connection, t, g (q on a manifold), v, mu,
/// xi (the Lie-group kernel) or Xi (n^2 numbers a row, the general solver), terminal_error,
/// xi_terminal, action (the Lie-group kernel), iterations {outer, inner, sweeps}, solve_time_s,
/// for collocation mesh_size, max_residual (and group_defect for the matrix groups), and frame0 on
/// a manifold. Throws std::invalid_argument for boundary data that are not elements of the group
/// (e.g. a gT that is not a rotation).
nlohmann::json solve(const ProblemSpec& spec, const SolveMonitor& monitor = {});

/// A Result as the result file's JSON (the library's writer, cartan/api/result_file.hpp, which
/// Python's to_json calls too). An interrupted result is its status alone: it is never written
/// (exit 130), so its trajectory is not formatted.
nlohmann::json result_json(const ProblemSpec& spec, api::Result result);

}  // namespace cartan::cli
