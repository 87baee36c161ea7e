// solve for the free body on SE(2), compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan::transported {
template TransportedSolution<groups::SE2> solve(const TransportedProblem<groups::SE2, mechanics::SE2FreeBody>&, const SolveOptions&,
                                        const SolveGuess<groups::SE2>&);
}  // namespace cartan::transported
