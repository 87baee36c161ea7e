#pragma once
// Shooting for the general problem (principle/manifold_problem.hpp): solve for (v0, Xi0) with the terminal conditions
// (difference(qT, q_N), Xi_N) = 0 by the library's Levenberg–Marquardt solver, with the
// dimensionless scaling of methods/lie_group/shooting.hpp: unknowns (T v0, Xi0 / s), residual
// (r_q, Xi_N / s), s = T |v_ref| |mu_ref| with v_ref the geodesic-guess velocity. The Jacobian is
// tangent-linear (tangent.hpp: one sweep carries the m + m^2 variations) or, with
// analytic_jacobian = false, by forward differences (1 + m + m^2 sweeps). The scheme is a kernel
// of the shooting driver (numerics/shooting_driver.hpp), the Lie-group scheme's: one algorithm,
// compiled once.

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/kernels/manifold/scheme.hpp"
#include "cartan/kernels/manifold/solution.hpp"
#include "cartan/kernels/manifold/tangent.hpp"
#include "cartan/numerics/nonlinear_solve.hpp"
#include "cartan/numerics/shooting_driver.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/solvers/shooting.hpp"
#include "cartan/status.hpp"

namespace cartan::general {

/// Runs the N steps from (v0, Xi0); returns the last node, or nothing (with `failure` set) when
/// the state became non-finite, a callback failed or `monitor` has a stop pending (polled about
/// every millisecond: SolveMonitor::stop_pending_at). ModelError passes through. With `tangent`,
/// the variations run along (tangent.hpp) and `jacobian` (m + m^2 square) receives
/// d (terminal_residual, Xi_N reshaped) / d (v0, Xi0 reshaped). `after_stop`: the work after a stop
/// in sweeps of this kind, projected by the polls until a sweep is timed (negative: by kind).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
std::optional<GeneralNode<M>> general_sweep(const GeneralScheme<M, L>& scheme, const manifolds::ComponentsOf<M>& v0,
                                            const manifolds::ComponentMatrixOf<M>& Xi0, std::string& failure,
                                            GeneralTrajectory<M>* trajectory, const GeneralSchemeTangent<M, L>* tangent,
                                            Eigen::MatrixXd* jacobian, const SolveMonitor* monitor, double after_stop) {
  constexpr int m = M::kDim;
  const auto begin = std::chrono::steady_clock::now();
  try {
    GeneralNode<M> node = scheme.initial(v0, Xi0), next;
    GeneralNodeTangent<M> dnode, dnext;
    if (tangent) dnode = tangent->initial(node);
    if (trajectory) trajectory->clear(), trajectory->push(node);
    // Until a sweep is timed, what follows a stop is projected: `after_stop`, else by kind.
    const double after =
        after_stop >= 0 ? after_stop : SolveMonitor::sweeps_after_stop(trajectory != nullptr, tangent != nullptr);
    for (int k = 0; k < scheme.problem().N; ++k) {
      if (SolveMonitor::stop_pending_at(monitor, k, scheme.problem().N, begin, after)) {
        failure = SolveMonitor::stopped_message(k);
        return std::nullopt;
      }
      tangent ? tangent->step(node, dnode, next, dnext) : scheme.step(node, next);
      if (!next.q.allFinite() || !next.frame.allFinite() || !next.mu.allFinite() || !next.Xi.allFinite() ||
          !next.v.allFinite() ||
          (tangent && !(dnext.q.allFinite() && dnext.frame.allFinite() && dnext.mu.allFinite() && dnext.Xi.allFinite()))) {
        failure = "non-finite state at step " + std::to_string(k + 1);
        return std::nullopt;
      }
      node = next;
      if (tangent) dnode = dnext;
      if (trajectory) trajectory->push(node);
    }
    if (tangent && jacobian) {
      jacobian->resize(m + m * m, m + m * m);
      *jacobian << tangent->terminal_residual_tangent(node, dnode), dnode.Xi;
    }
    return node;
  } catch (const ModelError&) {
    throw;
  } catch (const std::exception& e) {
    failure = e.what();
    return std::nullopt;
  }
}

namespace detail {

/// The general scheme as a kernel of the shooting driver (numerics/shooting_driver.hpp), the one
/// the Lie-group scheme uses: unknowns y = (v0, Xi0 reshaped), residual (r_q, Xi_N reshaped), the
/// Jacobian by the tangent-linear sweep (tangent.hpp). A sweep ending where difference(qT, .) is
/// not defined (the cut locus of qT, or outside the domain) fails: r_q would be meaningless there.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
class GeneralShootingKernel final : public numerics::ShootingKernel {
 public:
  GeneralShootingKernel(const GeneralScheme<M, L>& scheme, const SolveMonitor* monitor, GeneralSolution<M>& solution)
      : scheme_(scheme), tangent_(scheme), monitor_(monitor), solution_(solution) {}

  numerics::SweepEnd sweep(const Eigen::VectorXd& y, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, int slot,
                           double after_stop, std::string& failure) override {
    GeneralTrajectory<M>* trajectory = slot >= 0 ? &buffers_[static_cast<std::size_t>(slot)] : nullptr;
    const auto last = general_sweep(scheme_, velocity(y), auxiliary(y), failure, trajectory,
                                    jacobian != nullptr ? &tangent_ : nullptr, jacobian, monitor_, after_stop);
    if (!last) return numerics::SweepEnd::Failed;
    if (!scheme_.terminal_residual_defined(last->q)) {
      failure = "q_N = " + format_value(last->q) + " is where difference(qT, .) is not defined (the cut locus of qT " +
                "or outside the domain)";
      return numerics::SweepEnd::Undefined;
    }
    r.resize(m + m * m);
    r << scheme_.terminal_residual(*last), last->Xi.reshaped();
    return numerics::SweepEnd::Done;
  }

  bool record_result(const Eigen::VectorXd& y, int slot) override {
    std::optional<GeneralNode<M>> last;
    if (slot >= 0) {
      solution_.trajectory = std::move(buffers_[static_cast<std::size_t>(slot)]);
      last = solution_.trajectory.back();
    } else {
      std::string failure;
      last = general_sweep(scheme_, velocity(y), auxiliary(y), failure, &solution_.trajectory);
    }
    if (!last) {
      solution_.trajectory = {};  // never a partial trajectory
      return false;
    }
    solution_.v0 = velocity(y);
    solution_.Xi0 = auxiliary(y);
    solution_.terminal_error = scheme_.terminal_error(last->q);
    solution_.xi_terminal = last->Xi.norm();
    return true;
  }

 private:
  static constexpr int m = M::kDim;
  static manifolds::ComponentsOf<M> velocity(const Eigen::VectorXd& y) { return y.head<m>(); }
  static manifolds::ComponentMatrixOf<M> auxiliary(const Eigen::VectorXd& y) { return y.tail<m * m>().reshaped(m, m); }
  const GeneralScheme<M, L>& scheme_;
  const GeneralSchemeTangent<M, L> tangent_;
  const SolveMonitor* monitor_;
  GeneralSolution<M>& solution_;
  std::array<GeneralTrajectory<M>, 2> buffers_;  ///< the driver's two recording buffers
};

}  // namespace detail

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve_general_shooting(const GeneralProblem<M, L>& problem, const GeneralShootingOptions& options,
                                          const manifolds::ComponentsOf<M>& v0_guess,
                                          const manifolds::ComponentMatrixOf<M>& Xi0_guess) {
  problem.validate();
  options.validate();
  require_finite(v0_guess, "solve_general_shooting", "v0_guess");
  require_finite(Xi0_guess, "solve_general_shooting", "Xi0_guess");
  constexpr int m = M::kDim;
  const auto start = std::chrono::steady_clock::now();
  const GeneralScheme<M, L> scheme(problem, options.order);
  GeneralSolution<M> solution;
  solution.order = static_cast<int>(options.order);
  const double s = xi_scale(problem);
  detail::GeneralShootingKernel<M, L> kernel(scheme, options.monitor, solution);
  Eigen::VectorXd y0(m + m * m);
  y0 << v0_guess, Xi0_guess.reshaped();
  const numerics::ShootingOutcome outcome =
      solvers::shoot(kernel, m, problem.T, s, xi_size(problem), options, y0,
                     {"general shooting", "tangent-linear", "Xi",
                      scheme.uses_constant_components() ? ", constant frame components" : ""},
                     solution);
  // Never a wrong "converged": Levenberg–Marquardt's residual is small, but q_N is not at qT.
  if (outcome.has_trajectory && solution.converged() && !(solution.terminal_error <= options.tolerance)) {
    solution.status = Status::NotConverged;
    solution.message += "; but q_N is " + format_value(solution.terminal_error) + " from qT: not converged";
  }
  solution.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return solution;
}

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> solve_general_shooting(const GeneralProblem<M, L>& problem, const GeneralShootingOptions& options) {
  problem.validate();
  return solve_general_shooting(problem, options, geodesic_guess(problem), manifolds::ComponentMatrixOf<M>::Zero());
}

}  // namespace cartan::general
