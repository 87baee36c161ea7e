// solve for the free body on SE(3), compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan::transported {
template TransportedSolution<groups::SE3> solve(const TransportedProblem<groups::SE3, mechanics::SE3FreeBody>&, const SolveOptions&,
                                        const SolveGuess<groups::SE3>&);
}  // namespace cartan::transported
