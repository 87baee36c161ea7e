#pragma once
// `cartan solve`: builds the TransportedProblem a ProblemSpec describes, runs the chosen solver
// and reports the result as JSON (the CLI contract in docs/reference.md).

#include <nlohmann/json.hpp>

#include "cartan/monitor.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/transported/solve_options.hpp"
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
transported::SolveOptions solve_options(const ProblemSpec& spec);

/// Solves a validated spec with the library's solve (transported/solve.hpp) for the spec's model
/// (models::visit_model, models/catalogue.hpp). The JSON has status, message, group, model, lambda, T, N,
/// method, order, branch, t, g, v, mu, xi, terminal_error, xi_terminal, action, iterations
/// {outer, inner, sweeps}, solve_time_s, and for collocation mesh_size, max_residual (and
/// group_defect for the matrix groups). Throws std::invalid_argument for boundary data that are
/// not elements of the group (e.g. a gT that is not a rotation).
nlohmann::json solve(const ProblemSpec& spec, const SolveMonitor& monitor = {});

}  // namespace cartan::cli
