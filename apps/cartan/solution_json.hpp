#pragma once
// A TransportedSolution as the JSON of the CLI contract (docs/reference.md): trajectories as rows, a
// matrix element (so3, se2, se3) as its numbers row-major, a vector (a Heisenberg element, v, mu,
// xi) as its n numbers.

#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "cartan/general/solution.hpp"
#include "cartan/transported/solution.hpp"
#include "cartan/models/catalogue.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

/// One row per element: its numbers (models::element_numbers: a matrix row-major, a vector as it is).
template <class Value>
nlohmann::json rows(const std::vector<Value>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& x : values) out.push_back(models::element_numbers(x));
  return out;
}

/// A number for JSON: NaN and infinities (which JSON lacks) become null.
inline nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

/// Collocation's mesh_size, max_residual and (matrix groups) group_defect, when present.
inline void add_collocation_report(nlohmann::json& out, const std::optional<transported::CollocationReport>& report) {
  if (!report) return;
  out["mesh_size"] = report->mesh_size;
  out["max_residual"] = report->max_residual;
  if (std::isfinite(report->group_defect)) out["group_defect"] = report->group_defect;
}

/// Every key of a `cartan solve` result: result_header, the connection ("connection":
/// "cartan-schouten" with "lambda", and "side": "left", the trivialisation of v), the trajectory
/// (t, g, v, mu, xi), the diagnostics (terminal_error, xi_terminal, action, iterations,
/// solve_time_s) and, for collocation, mesh_size, max_residual and (matrix groups) group_defect.
/// `order` is the scheme's order (1 or 2 for the discrete schemes, 2 for variational, 4 for
/// collocation). python/cartan/_results.py writes and reads the same keys.
template <groups::LieGroup G>
nlohmann::json solution_json(const ProblemSpec& spec, const transported::TransportedSolution<G>& s) {
  const auto& tr = s.trajectory;
  nlohmann::json out = result_header(spec, std::string(to_string(s.status)), s.message,
                                     std::string(to_string(s.method)), s.order, s.branch);
  if (s.status == Status::Interrupted) return out;  // never written (exit 130): no trajectory to format
  out["connection"] = "cartan-schouten";
  out["side"] = "left";
  out["t"] = tr.t;
  out["g"] = rows(tr.g);
  out["v"] = rows(tr.v);
  out["mu"] = rows(tr.mu);
  out["xi"] = rows(tr.xi);
  out["terminal_error"] = s.terminal_error;
  out["xi_terminal"] = s.xi_terminal;
  out["iterations"] = {{"outer", s.outer_iterations}, {"inner", s.inner_iterations}, {"sweeps", s.sweeps}};
  out["action"] = number_or_null(s.action);
  out["solve_time_s"] = s.solve_time_s;
  add_collocation_report(out, s.collocation);
  return out;
}

/// The trajectory and diagnostics of a general solution (general/shooting.hpp) under `point_key`
/// ("q" on a manifold, "g" on a group): t, the points, v, mu, Xi (n^2 numbers a row, row-major),
/// terminal_error, xi_terminal (|Xi_N|), iterations {outer: 0, inner, sweeps}, solve_time_s and,
/// for collocation, mesh_size and max_residual.
template <manifolds::ManifoldWithConnection M>
void add_general_solution(nlohmann::json& out, const general::GeneralSolution<M>& s, const char* point_key) {
  if (s.status == Status::Interrupted) return;  // never written (exit 130): no trajectory to format
  out["t"] = s.trajectory.t;
  out[point_key] = rows(s.trajectory.q);
  out["v"] = rows(s.trajectory.v);
  out["mu"] = rows(s.trajectory.mu);
  out["Xi"] = rows(s.trajectory.Xi);
  out["terminal_error"] = s.terminal_error;
  out["xi_terminal"] = s.xi_terminal;
  out["iterations"] = {{"outer", 0}, {"inner", s.iterations}, {"sweeps", s.sweeps}};
  out["solve_time_s"] = s.solve_time_s;
  add_collocation_report(out, s.collocation);
}

}  // namespace cartan::cli
