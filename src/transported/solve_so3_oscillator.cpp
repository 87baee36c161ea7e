// solve for the SO(3) oscillator, compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan::transported {
template TransportedSolution<groups::SO3> solve(const TransportedProblem<groups::SO3, mechanics::SO3Oscillator>&, const SolveOptions&,
                                        const SolveGuess<groups::SO3>&);
}  // namespace cartan::transported
