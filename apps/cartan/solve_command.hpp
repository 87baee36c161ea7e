#pragma once
// `cartan solve`: builds the TransportedProblem a ProblemSpec describes, runs the chosen solver
// and reports the result as JSON (the CLI contract in README.md).

#include <nlohmann/json.hpp>

#include "problem_spec.hpp"

namespace cartan::cli {

/// Solves a validated spec. The JSON has status, message, group, model, lambda, T, N, method,
/// order, branch, t, g, v, mu, xi, terminal_error, iterations {outer, inner, sweeps}, solve_time_s.
/// Throws std::invalid_argument for bad boundary data (e.g. a0 = -aT, a non-rotation gT).
nlohmann::json solve(const ProblemSpec& spec);

}  // namespace cartan::cli
