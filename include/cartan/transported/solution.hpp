#pragma once
// What every transported-velocity solver returns: a status and diagnostics, never a silent
// trajectory (DESIGN.md "Results, not exceptions, for numerics").

#include <string>
#include <vector>

#include "cartan/transported/scheme.hpp"

namespace cartan {

template <LieGroup G>
struct TransportedSolution {
  bool converged = false;
  std::string status;   ///< "converged" or a failure word (max-iterations, stalled, non-finite, ...)
  std::string message;  ///< human-readable diagnostics (iterations, residuals)
  std::string method;   ///< two-level | shooting | multiple-shooting | continuation
  std::string branch;   ///< how the solution was reached (initial guess, continuation path)
  int order = 1;
  TransportedTrajectory<G> trajectory;
  TangentOf<G> v0 = TangentOf<G>::Zero();
  CovectorOf<G> xi0 = CovectorOf<G>::Zero();
  double terminal_error = 0;  ///< |log(gT^{-1} g_N)|
  double xi_terminal = 0;     ///< |xi_N| (0 by construction in the two-level scheme)
  int outer_iterations = 0;
  int inner_iterations = 0;
  int sweeps = 0;             ///< forward sweeps of the scheme (tangent sweeps count once)
  std::vector<double> residual_history;
  double solve_time_s = 0;
};

}  // namespace cartan
