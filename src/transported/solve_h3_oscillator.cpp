// solve for the Heisenberg oscillator, compiled once (transported/solve.hpp).
#include "cartan/transported/solve.hpp"

namespace cartan {
template TransportedSolution<Heisenberg> solve(const TransportedProblem<Heisenberg, H3Oscillator>&,
                                               const SolveOptions&, const SolveGuess<Heisenberg>&);
}  // namespace cartan
