#pragma once
// The result file (layer "api"): the JSON `cartan solve --output` writes, `cartan verify` checks,
// and Python's SolveResult.to_json and cartan.load write and read. One writer (result_json) and
// one reader (read_result), so the CLI and Python cannot drift apart (docs/reference.md, "Output"
// of `cartan solve`). Compiled once in cartan::io (src/api/result_file.cpp), which the Python module links
// as well; this header declares only (nlohmann's forward declarations).
//
// Keys: status, message, method, order, branch; the problem echoed (on a group: group, model,
// inertia, lambda, T, N, tol, g0, gT, connection and side "left" | metric | alpha; on a space of
// api/spaces.hpp: manifold, model "particle" (or "python:<type name>"), mass (m numbers or m rows),
// gravity, connection with lambda | metric | alpha, q0, qT, frame0 (its m rows e_i), T, N, tol);
// the samples t, g (q), v, mu, xi (the Lie-group kernel) or Xi (m^2 numbers a row); terminal_error,
// xi_terminal, iterations {outer, inner, sweeps}, action (the Lie-group kernel), solve_time_s;
// collocation: mesh_size, max_residual, group_defect (where finite). NaN and infinities are null.
// A manifold file of an earlier version (the quadrics' particle with mass a1, a2, no connection)
// reads as the same problem: the space's default connection, frame0 as it recorded it.

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <variant>

#include "cartan/api/solve.hpp"
#include "cartan/api/spaces.hpp"

namespace cartan::api {

/// The prefix of the model name of a Lagrangian defined in Python ("python:<type name>"): a file
/// records its name, not its code, so it is read but never rebuilt (api::verify refuses it).
inline constexpr std::string_view kPythonModelPrefix = kPythonPrefix;

/// What a result file holds: the problem as solved, the tolerance asked for, and the result.
struct ResultRecord {
  std::variant<GroupProblem, ManifoldProblem> problem;
  double tol = kDefaultTol;
  Result result;

  bool on_manifold() const { return std::holds_alternative<ManifoldProblem>(problem); }
};

/// The record as the file's JSON object. A group problem's inertia of n^2 numbers is written as
/// rows, of n numbers (the diagonal) as a list; gT as given (the caller's final element).
nlohmann::json result_json(const ResultRecord& record);

/// Reads a result file's object: every key the format defines, with its type and shape (the rows
/// of every table as many as the times, of the widths of the problem's group or manifold), the
/// words (status, method, connection, side), the order, and the group and model (a model of the
/// catalogue, or kPythonModelPrefix + a name). null is NaN wherever a number may be one
/// (diagnostics, rows of a failed solve). Required: status, method, order, the problem, tol and
/// the samples; the diagnostics (message, branch, terminal_error, xi_terminal, iterations,
/// action, solve_time_s) may be absent, so that a trajectory computed elsewhere can be checked:
/// then empty, NaN and 0 iterations. Throws std::invalid_argument "<where>: <key> = <value>
/// <problem>" at the first bad or missing key, and no other exception. Not checked here: that
/// the problem is well posed (api::check, which api::verify runs) and the samples' values
/// (read_solution).
ResultRecord read_result(const nlohmann::json& j, std::string_view where);

/// read_result, then what the checks of a solution assume of its samples (what `cartan verify`
/// reads): at least 2 strictly increasing times from 0 to T (to 1e-6 T), every number finite,
/// and on a group every row of g an element of it. Throws as read_result.
ResultRecord read_solution(const nlohmann::json& j, std::string_view where);

/// Parses `text` (io::parse_json) and reads it with read_result: what Python's cartan.load calls.
ResultRecord read_result_text(const std::string& text, std::string_view where);

/// result_json(record) as one line of text with a final newline: what Python's to_json writes.
std::string result_text(const ResultRecord& record);

}  // namespace cartan::api
