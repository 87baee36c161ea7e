#pragma once
// `cartan solve --method collocation`: the transported BVP (eq:reduced-system) solved by the
// fourth-order collocation solver, reported with the same JSON keys as the other methods plus
// mesh_size and max_residual; t, g, v, mu, xi are sampled from the dense output at `samples`
// uniform times (the final mesh when samples = 0).
//  * heisenberg: the paper's printed system (bvp/heisenberg_transported.hpp), xi by quadrature.
//  * so3: the generic system with g and the transport element as matrix states
//    (bvp/transported_collocation.hpp), also reporting group_defect = max |g^T g - I| over the
//    mesh. When collocation from the geodesic guess fails and --continuation is not none, it
//    starts again from the order-2 shooting solution (continued as --continuation says), and the
//    result's branch says so.

#include <nlohmann/json.hpp>

#include "cartan/models/heisenberg_oscillator.hpp"
#include "cartan/models/rigid_body.hpp"
#include "cartan/transported/problem.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<Heisenberg, H3Oscillator>& problem);
nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<SO3, RigidBody>& problem);
nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<SO3, SO3Oscillator>& problem);

}  // namespace cartan::cli
