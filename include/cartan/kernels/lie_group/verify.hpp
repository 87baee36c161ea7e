#pragma once
// The checks of kernels/lie_group/verify_checks.hpp run on a solution of the transported-velocity BVP, as a
// verdict (verify/verdict.hpp: each check with its figure, its threshold and PASS / FAIL / N/A).
// `cartan verify` (CLI) and `cartan.verify` (Python) print this report; C++ users call
// verify_solution on any result of any model. docs/verify.md explains each check and where its
// threshold comes from. verify_trajectory is declared in kernels/lie_group/compiled.hpp (with what the
// library compiles of it) and defined here.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "cartan/errors.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/lie_group/solution.hpp"
#include "cartan/kernels/lie_group/verify_checks.hpp"
#include "cartan/principle/horizon.hpp"
#include "cartan/scheme_order.hpp"
#include "cartan/verify/assemble.hpp"
#include "cartan/verify/verdict.hpp"

namespace cartan::verify {

/// Runs every check on `x`, a solution of `problem` (its Lagrangian, lambda, T, g0, gT; N is not
/// used: x may have any number of samples) computed to tolerance `tol` by a method of the given
/// order (1, 2, or 4 for collocation). A `status` other than converged adds a failing
/// `converged` check (the data are then a best iterate). Throws std::invalid_argument for an
/// invalid order or tol, and an invalid trajectory (TransportedTrajectory::validate, with mu) of a
/// converged result (a failed one's is a diverged iterate: its report fails, saying so).
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
Report verify_trajectory(const transported::TransportedProblem<G, L>& problem, transported::TransportedTrajectory<G> x, int order, double tol,
                         Status status) {
  require_result_order(order, "verify");
  require_tolerance(tol, "verify");
  try {
    x.validate(problem.T, "verify", true, 1e-9);
  } catch (const std::invalid_argument& e) {
    if (status == Status::Converged) throw;
    return unchecked_failure(status, e.what());  // a diverged iterate: FAIL, saying why
  }
  const TrajectoryChecks<G, L> checks(problem.lagrangian, problem.lambda, problem.T, std::move(x));
  Figures f;
  f.resolution = checks.max_step() * checks.frequency();
  f.amplification = checks.amplification();
  // Shooting stops at |xi_N| / xi_scale <= tol (shooting.hpp), so xi_N may exceed tol where
  // xi_scale > 1: measure it in units of max(1, xi_scale), never looser than absolute.
  const double xi_unit = std::max(1.0, transported::xi_scale(problem));
  f.boundary = checks.boundary_error(problem.g0, problem.gT, xi_unit);
  f.boundary_note = "max(|log(g0^-1 g_0)|, |log(gT^-1 g_N)|, |xi_N| / max(1, xi_scale)) against tol";
  f.legendre = checks.legendre_residual();
  f.legendre_note = "max |mu - dl/dv(g, v)|, relative";
  f.energy = checks.energy_drift();
  f.energy_note = "max |E - E(0)| / max |E|, E = mu.v - l (conserved for every lambda when l does not depend on t)";
  f.residual = checks.equation_residual();
  f.residual_equations = "eq:reduced-system";
  f.step_roundoff = checks.samples_roundoff();
  if (is_uniform(checks.trajectory().t)) {
    f.stationarity = checks.action_stationarity(kVariations, kVariationSeed);
  } else {
    f.stationarity_note = kNonUniformStationarityNote;
  }
  return assemble(f, order, tol, status);
}

}  // namespace cartan::verify
