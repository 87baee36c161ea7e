// solve for the Heisenberg oscillator, compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan::transported {
template TransportedSolution<groups::Heisenberg> solve(const TransportedProblem<groups::Heisenberg, mechanics::H3Oscillator>&,
                                               const SolveOptions&, const SolveGuess<groups::Heisenberg>&);
}  // namespace cartan::transported
