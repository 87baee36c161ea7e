// solve for the free rigid body on SO(3), compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan {
template TransportedSolution<SO3> solve(const TransportedProblem<SO3, RigidBody>&, const SolveOptions&,
                                        const SolveGuess<SO3>&);
}  // namespace cartan
