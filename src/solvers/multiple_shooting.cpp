// Multiple shooting's driver (solvers/multiple_shooting.hpp).
#include "cartan/solvers/multiple_shooting.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cartan/errors.hpp"
#include "cartan/numerics/nonlinear_solve.hpp"
#include "cartan/numerics/spectrum.hpp"

namespace cartan::solvers {

namespace {

/// The largest lifted Jacobian whose conditioning a failure reports: its one-sided Jacobi SVD
/// costs about (columns / 256)^3 0.7 s here (7 s at 576 columns, 64 segments of SO(3)), more
/// than the solve it would explain.
constexpr Eigen::Index kMaxConditioningColumns = 256;

/// "; sigma_min / sigma_max of the Jacobian at the last point: <ratio>" of the lifted Jacobian at
/// x (NaN if the evaluation failed): a value near rounding means LM stopped at a local minimum of
/// |r| on a fold, not near a root. Past kMaxConditioningColumns it says it was not computed.
std::string jacobian_conditioning(LiftedSystem& system, const Eigen::VectorXd& x, int& sweeps) {
  if (x.size() > kMaxConditioningColumns) {
    return "; the Jacobian's conditioning is not computed for " + std::to_string(x.size()) +
           " unknowns (its SVD would cost more than the solve)";
  }
  ++sweeps;
  Eigen::VectorXd r;
  Eigen::MatrixXd jac;
  const double ratio = system.evaluate(x, r, &jac) ? numerics::singular_value_ratio(jac) : std::nan("");
  return "; sigma_min / sigma_max of the Jacobian at the last point: " + format_value(ratio);
}

}  // namespace

void solve_lifted(LiftedSystem& system, const LiftedOptions& options, const std::string& header, ResultCore& result) {
  std::ostringstream message;
  message << header;
  if (options.segments > 1) ++result.sweeps;
  std::optional<Eigen::VectorXd> x = system.initialise();
  if (!x) {
    const bool stopped = options.monitor != nullptr && options.monitor->stop_requested();
    result.status = stopped ? Status::Interrupted : Status::NonFinite;
    result.message = message.str() + "the initial segment states failed: " + system.failure();
    return;
  }
  const numerics::ResidualFunction f = [&](const Eigen::VectorXd& y, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
    ++result.sweeps;
    return system.evaluate(y, r, jac);
  };
  // Rounds of LM, re-centring the charts in between (the first point of a round repeats the
  // last of the previous one and is not recorded twice).
  numerics::NonlinearSolveReport report;
  double lifted_tolerance = options.tolerance;
  int rounds = 0, tightenings = 0;
  bool lifted_converged = false;
  while (result.inner_iterations < options.max_iterations) {
    const int budget = std::min(options.recentre_every, options.max_iterations - result.inner_iterations);
    report = numerics::levenberg_marquardt(f, *x, {.tolerance = lifted_tolerance, .max_iterations = budget,
                                                   .monitor = options.monitor, .evaluations_stop = true});  // segments poll
    result.inner_iterations += report.iterations;
    const auto& h = report.residual_history;
    result.residual_history.insert(result.residual_history.end(), h.begin() + (rounds > 0 && !h.empty()), h.end());
    ++rounds;
    *x = report.x;
    if (report.status == Status::MaxIterations) {
      system.recentre(*x);
      continue;
    }
    // Below the tolerance; after a tightening, a stall at the rounding floor counts too.
    lifted_converged = report.status == Status::Converged || (tightenings > 0 && report.status == Status::Stalled);
    if (!lifted_converged) break;
    ++result.sweeps;
    const double single = system.single_sweep_residual(*x);
    if (single <= options.tolerance || tightenings == 3) break;
    ++tightenings;
    lifted_tolerance = report.residual_norm * 0.5 * options.tolerance / single;
    if (!(lifted_tolerance > 0)) break;  // single is inf (its sweep failed) or |r| is exactly 0
  }
  ++result.sweeps;
  const bool recorded = system.record(*x);
  const bool consistent = recorded && std::hypot(result.terminal_error, result.xi_terminal / system.auxiliary_scale()) <=
                                          options.tolerance;
  result.status = !recorded                        ? Status::NonFinite
                  : lifted_converged && consistent ? Status::Converged
                  : lifted_converged               ? Status::Inconsistent
                                                   : report.status;
  // Why LM stopped short, for a failure of its own; a stop on request (Ctrl-C, time_limit) ends
  // now: the diagnostic's Jacobian and SVD took seconds after the limit at 64 segments.
  std::string conditioning;
  if (!lifted_converged && report.status != Status::Interrupted) {
    conditioning = jacobian_conditioning(system, *x, result.sweeps);
  }
  message << report.message << " in round " << rounds << " (" << result.inner_iterations
          << " iterations in all, lifted tolerance " << format_value(lifted_tolerance) << "), " << result.sweeps
          << " sweeps; |r| history [";
  for (std::size_t i = 0; i < result.residual_history.size(); ++i) {
    message << (i ? ", " : "") << format_value(result.residual_history[i]);
  }
  message << "]";
  if (recorded) {
    message << "; single sweep from v0: terminal error " << format_value(result.terminal_error) << ", |xi_N| "
            << format_value(result.xi_terminal);
  }
  message << conditioning;
  if (!system.failure().empty()) message << "; last failed segment sweep: " << system.failure();
  result.message = message.str();
}

}  // namespace cartan::solvers
