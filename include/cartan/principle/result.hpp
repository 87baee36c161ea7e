#pragma once
// What results of every kernel share (DESIGN.md, layer "principle"): a status and diagnostics,
// never a silent trajectory (DESIGN.md "Results, not exceptions, for numerics"). Each kernel's
// solution adds its trajectory and its unknowns (kernels/lie_group/solution.hpp: v0, xi0;
// kernels/manifold/solution.hpp: v0, Xi0); api::Result adds them as numbers.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cartan/principle/vocabulary.hpp"
#include "cartan/status.hpp"

namespace cartan {

/// What only collocation reports: the final mesh size, the largest relative RMS residual on it,
/// and for SO(3) max |g^T g - I| over the mesh of g and the transport element (NaN elsewhere).
struct CollocationReport {
  int mesh_size = 0;
  double max_residual = 0;
  double group_defect = std::numeric_limits<double>::quiet_NaN();
};

struct ResultCore {
  Status status = Status::NotConverged;
  std::string message;  ///< human-readable diagnostics (iterations, residuals, every attempt)
  Method method = Method::Shooting;  ///< the method that produced this result (never Auto)
  std::string branch;   ///< how the solution was reached (guess, continuation path, strategy)
  int order = 1;        ///< of the discrete scheme (1, 2), the variational integrator (2) or collocation (4)
  /// The distance of the last node from the target: |log(gT^{-1} g_N)| on a group,
  /// separation(qT, q_N) on a manifold (|difference(qT, q_N)| where it is a logarithm).
  double terminal_error = 0;
  double xi_terminal = 0;     ///< |xi_N| or |Xi_N| (0 by construction in the two-level scheme)
  int outer_iterations = 0;   ///< two-level's fixed point, collocation's refinements
  int inner_iterations = 0;   ///< Levenberg–Marquardt's or Newton's
  int sweeps = 0;             ///< forward sweeps of the scheme (tangent sweeps count once)
  std::vector<double> residual_history;
  double solve_time_s = 0;
  /// The discrete transported action S_h of the trajectory (kernels/lie_group/action.hpp), so that users
  /// can tell solution branches apart; NaN where the kernel computes none (the general kernel),
  /// when there is no trajectory, or when the solve was stopped on request (interrupted, time-limit).
  double action = std::numeric_limits<double>::quiet_NaN();
  std::optional<CollocationReport> collocation;  ///< set by collocation only

  bool converged() const { return status == Status::Converged; }
};

}  // namespace cartan
