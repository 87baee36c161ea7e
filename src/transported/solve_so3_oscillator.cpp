// solve for the SO(3) oscillator, compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan {
template TransportedSolution<SO3> solve(const TransportedProblem<SO3, SO3Oscillator>&, const SolveOptions&,
                                        const SolveGuess<SO3>&);
}  // namespace cartan
