#pragma once
// Augmented shooting (beyond the paper): integrate xi forward from an unknown xi0 and solve for
// (v0, xi0) with the terminal conditions (log(gT^{-1} g_N), xi_N) = 0 in one Levenberg–Marquardt
// problem. Its solution satisfies the same discrete equations as the fixed point of the paper's
// two-level scheme (xi_k from the backward recursion with xi_N = 0), without the outer loop.
// The Jacobian is analytic (a tangent-linear sweep, one sweep per evaluation) or by forward
// differences (1 + 2n sweeps). The scheme is a kernel of the shooting driver
// (numerics/shooting_driver.hpp), which the general scheme shares: the decisions are compiled once.
//
// Scale. The unknowns and residual are made dimensionless so that the same tolerance means the
// same at every horizon: v0 in units of 1/T, xi in units of the curvature integral's size
// xi_scale = T |v_ref| |mu_ref| (v_ref the geodesic velocity at a speed of at least 1/T, mu_ref its
// momentum at g0: principle/scales.hpp; for a kinetic Lagrangian the problem at horizon cT is then
// the same problem). The convergence test
// is |(log(gT^{-1} g_N), xi_N / xi_scale)| <= tolerance: radians, and a relative xi.

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/lie_group/solution.hpp"
#include "cartan/kernels/lie_group/solve_options.hpp"
#include "cartan/kernels/lie_group/sweep.hpp"
#include "cartan/numerics/nonlinear_solve.hpp"
#include "cartan/numerics/shooting_driver.hpp"
#include "cartan/solvers/shooting.hpp"

namespace cartan::transported {

namespace detail {

/// Final recorded sweep shared by the solvers: fills trajectory and terminal figures. With
/// `recorded` (the trajectory of a sweep from the same v0 and xi0), takes it instead of sweeping.
/// The sweep it makes without `recorded` is the caller's to count, as the solvers' other sweeps.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
bool record_solution(const TransportedScheme<G, L>& scheme, const groups::TangentOf<G>& v0, const groups::CovectorOf<G>& xi0,
                     const std::vector<groups::CovectorOf<G>>* given_xi, TransportedSolution<G>& solution,
                     TransportedTrajectory<G>* recorded = nullptr) {
  if (recorded != nullptr) {
    solution.trajectory = std::move(*recorded);
  } else {
    SweepOutput<G, L> out;
    out.trajectory = &solution.trajectory;
    if (!forward_sweep(scheme, v0, xi0, given_xi, 0, out)) {
      solution.trajectory = {};  // never a partial trajectory
      return false;
    }
  }
  const TransportedTrajectory<G>& tr = solution.trajectory;
  solution.v0 = v0;
  solution.xi0 = tr.xi.front();
  solution.terminal_error = groups::log_between<G>(scheme.problem().gT, tr.g.back()).norm();  // terminal_residual
  solution.xi_terminal = tr.xi.back().norm();
  return true;
}

/// The Lie-group scheme as a kernel of the shooting driver (numerics/shooting_driver.hpp): unknowns
/// y = (v0, xi0), residual (log(gT^{-1} g_N), xi_N), the Jacobian by the tangent-linear sweep.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class TransportedShootingKernel final : public numerics::ShootingKernel {
 public:
  TransportedShootingKernel(const TransportedScheme<G, L>& scheme, const SolveMonitor* monitor,
                            TransportedSolution<G>& solution)
      : scheme_(scheme), monitor_(monitor), solution_(solution) {}

  numerics::SweepEnd sweep(const Eigen::VectorXd& y, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, int slot,
                           double after_stop, std::string& failure) override {
    SweepOutput<G, L> out;
    out.monitor = monitor_;
    out.after_stop = after_stop;
    out.trajectory = slot >= 0 ? &buffers_[static_cast<std::size_t>(slot)] : nullptr;
    if (!forward_sweep(scheme_, groups::TangentOf<G>(y.head<n>()), groups::CovectorOf<G>(y.tail<n>()), nullptr,
                       jacobian != nullptr ? 2 * n : 0, out)) {
      failure = out.failure;
      return numerics::SweepEnd::Failed;
    }
    const groups::TangentOf<G> rg = scheme_.terminal_residual(out.last);
    r.resize(2 * n);
    r << rg, out.last.xi;
    if (jacobian != nullptr) {
      jacobian->resize(2 * n, 2 * n);
      jacobian->topRows(n) = scheme_.terminal_residual_tangent(rg, *out.tangent);
      jacobian->bottomRows(n) = out.tangent->xi;
    }
    return numerics::SweepEnd::Done;
  }

  bool record_result(const Eigen::VectorXd& y, int slot) override {  // the driver counts the sweep
    return record_solution(scheme_, groups::TangentOf<G>(y.head<n>()), groups::CovectorOf<G>(y.tail<n>()), nullptr,
                           solution_, slot >= 0 ? &buffers_[static_cast<std::size_t>(slot)] : nullptr);
  }

 private:
  static constexpr int n = G::kDim;
  const TransportedScheme<G, L>& scheme_;
  const SolveMonitor* monitor_;
  TransportedSolution<G>& solution_;
  std::array<TransportedTrajectory<G>, 2> buffers_;  ///< the driver's two recording buffers
};

}  // namespace detail

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_shooting(const TransportedProblem<G, L>& problem, const ShootingOptions& options,
                                      const groups::TangentOf<G>& v0_guess, const groups::CovectorOf<G>& xi0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_shooting", "v0_guess");
  require_finite(xi0_guess, "solve_shooting", "xi0_guess");
  constexpr int n = G::kDim;
  const auto start = std::chrono::steady_clock::now();
  const TransportedScheme<G, L> scheme(problem, options.order);
  TransportedSolution<G> solution;
  solution.method = Method::Shooting;
  solution.order = static_cast<int>(options.order);
  // Dimensionless unknowns (T v0, xi0 / s) and residual (r_g, xi_N / s) (header comment).
  const double s = xi_scale(problem);
  detail::TransportedShootingKernel<G, L> kernel(scheme, options.monitor, solution);
  Eigen::VectorXd y0(2 * n);
  y0 << v0_guess, xi0_guess;
  solvers::shoot(kernel, n, problem.T, s, xi_size(problem), options, y0, {"shooting", "analytic", "xi", ""}, solution);
  solution.solve_time_s = detail::seconds_since(start);
  return solution;
}

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
TransportedSolution<G> solve_shooting(const TransportedProblem<G, L>& problem, const ShootingOptions& options = {}) {
  problem.validate();
  return solve_shooting(problem, options, geodesic_guess(problem), groups::CovectorOf<G>::Zero());
}

}  // namespace cartan::transported

// Shooting on the erased Lagrangian of every shipped group is compiled once, in the library
// (src/methods/lie_group/erased_*.cpp): the Lie-group kernel inside general::solve shoots through it
// (methods/lie_group_as_manifold.hpp), so that no unit instantiates the scheme on its own Lagrangian type.
#define CARTAN_TRANSPORTED_SHOOTING_ERASED(prefix, G)                                                         \
  prefix ::cartan::transported::TransportedSolution<G> cartan::transported::solve_shooting(                  \
      const ::cartan::transported::ErasedProblem<G>&, const ::cartan::ShootingOptions&,                     \
      const ::cartan::groups::TangentOf<G>&, const ::cartan::groups::CovectorOf<G>&);
#define CARTAN_TRANSPORTED_EXTERN_SHOOTING(G) CARTAN_TRANSPORTED_SHOOTING_ERASED(extern template, G)
CARTAN_TRANSPORTED_SHIPPED_GROUPS(CARTAN_TRANSPORTED_EXTERN_SHOOTING)
#undef CARTAN_TRANSPORTED_EXTERN_SHOOTING

