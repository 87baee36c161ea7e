#pragma once
// `cartan solve --manifold sphere`: the general transported-velocity problem
// (include/cartan/general/solve.hpp) on S^2 with its Levi-Civita connection and the particle
// l = 1/2 (a1 v1^2 + a2 v2^2) - G z, v = (v1, v2) the transported velocity in the frame of T_{q0}S^2
// with e1 the unit tangent at q0 along the minimal great circle towards qT and e2 = q0 x e1.
// The result: the shared header (status, message, method, order, branch, echoed fields), t, q
// (points, one row per node), v and mu (2 numbers a row), Xi (4 numbers a row, row-major),
// frame0 (the rows e1, e2), terminal_error, xi_terminal, iterations, solve_time_s.

#include <nlohmann/json.hpp>

#include "cartan/general/erased_lagrangian.hpp"
#include "cartan/manifolds/quadric.hpp"
#include "cartan/monitor.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

using SphereParticle = general::KineticPotential<manifolds::Sphere>;
/// The particle behind the erased Lagrangian: the solve compiled in the library (general/compiled.hpp).
using SphereProblem = general::ErasedProblem<manifolds::Sphere>;

/// The problem of a validated --manifold sphere spec (its frame: e1 towards qT, e2 = q0 x e1).
SphereProblem sphere_problem(const ProblemSpec& spec);

/// Solves a validated --manifold problem (validate(spec) first). Throws std::invalid_argument for
/// what validate cannot see (a model callback's defect).
nlohmann::json solve_manifold(const ProblemSpec& spec, const SolveMonitor& monitor);

}  // namespace cartan::cli
