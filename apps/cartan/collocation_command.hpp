#pragma once
// `cartan solve --method collocation`: the H3 transported BVP (bvp/heisenberg_transported.hpp)
// solved by the collocation solver, reported with the same JSON keys as the other methods plus
// mesh_size; t, g, v, mu, xi are sampled from the dense output at `samples` uniform times
// (the final mesh when samples = 0).

#include <nlohmann/json.hpp>

#include "cartan/models/heisenberg_oscillator.hpp"
#include "cartan/transported/problem.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<Heisenberg, H3Oscillator>& problem);

}  // namespace cartan::cli
