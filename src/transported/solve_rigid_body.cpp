// solve for the free rigid body on SO(3), compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan::transported {
template TransportedSolution<groups::SO3> solve(const TransportedProblem<groups::SO3, mechanics::RigidBody>&, const SolveOptions&,
                                        const SolveGuess<groups::SO3>&);
}  // namespace cartan::transported
