#pragma once
// `cartan solve --group G --connection levi-civita|coefficients`: a model of the table under a
// left-invariant connection other than Cartan–Schouten, solved by the general solver
// (include/cartan/general/solve.hpp on manifolds::GroupManifold<G>, the model through
// general::OnGroupManifold). The result has the keys of a group result, with `Xi` (n^2 numbers a
// row, row-major) in place of `xi`, and `connection`, `metric` (levi-civita) or `alpha`
// (coefficients, as the nested array) echoed.

#include <nlohmann/json.hpp>

#include "cartan/monitor.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

/// Solves a validated group problem whose connection is not cartan-schouten.
nlohmann::json solve_with_connection(const ProblemSpec& spec, const SolveMonitor& monitor);

}  // namespace cartan::cli
