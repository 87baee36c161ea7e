#pragma once
// A collocation solver for two-point boundary-value problems
//   y' = f(t, y, p) on [a, b],   bc(y(a), y(b), p) = 0,   y in R^n, p in R^k (unknown parameters),
// with n + k boundary conditions. It solves the paper's reformulated BVP (eq:reduced-system)
// and any other first-order system.
//
// Method (the three-stage Lobatto IIIA / Simpson family, fourth order; Kierzenka & Shampine 2001):
//  * On each mesh interval [t_i, t_i + h] the solution is the C^1 cubic S with S(t_i) = y_i,
//    S(t_{i+1}) = y_{i+1}, S' = f at both ends; S' = f also at the midpoint gives
//      y_mid = (y_i + y_{i+1})/2 - h/8 (f_{i+1} - f_i),
//      r_i   = y_{i+1} - y_i - h/6 (f_i + 4 f(t_i + h/2, y_mid) + f_{i+1}) = 0.
//  * The n(m-1) collocation equations and the n + k boundary conditions are solved for all
//    nodes and p at once by damped Newton (natural monotonicity test on the Newton correction)
//    on the block-sparse Jacobian (collocation_jacobian.hpp: a structured partial-pivoting LU,
//    or Eigen's SparseLU). Jacobians of f and bc are the user's or
//    forward differences with steps fd_step * max(1, |x_j|). While Newton contracts by 4 or more
//    per full step, the factorised matrix is reused (chord steps; reuse_jacobian).
//  * Error control: the residual rho(t) = S'(t) - f(t, S(t)), relative to 1 + |f|, is O(h^3);
//    its RMS over each interval (5-point Lobatto quadrature; rho vanishes at both ends) must be
//    <= tol. An interval with residual r > tol is split into ceil((r / tol)^(1/3)) pieces (2 to
//    6), the solution is carried to the new mesh by S (warm start); the mesh never exceeds
//    max_nodes.
// Numerical outcomes are reported in BvpResult; only invalid arguments throw.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <string_view>

#include "cartan/numerics/cubic_hermite.hpp"
#include "cartan/monitor.hpp"
#include "cartan/status.hpp"

namespace cartan::numerics {

using VectorRef = Eigen::Ref<Eigen::VectorXd>;
using ConstVectorRef = const Eigen::Ref<const Eigen::VectorXd>&;
using MatrixRef = Eigen::Ref<Eigen::MatrixXd>;
using ConstMatrixRef = const Eigen::Ref<const Eigen::MatrixXd>&;

/// The problem. `rhs` and `bc` are required; the Jacobians and the batched forms are optional.
struct BvpSystem {
  int n = 0;  ///< state dimension
  int k = 0;  ///< number of unknown parameters
  /// dydt = f(t, y, p)  (dydt has size n).
  std::function<void(double t, ConstVectorRef y, ConstVectorRef p, VectorRef dydt)> rhs;
  /// Optional, f at many points in one call: column j of dydt (n x m) is f(t[j], y.col(j), p).
  /// When set, the solver evaluates each mesh sweep (nodes, midpoints, quadrature points) with
  /// one call instead of one per point; it must agree with rhs.
  std::function<void(ConstVectorRef t, ConstMatrixRef y, ConstVectorRef p, MatrixRef dydt)> rhs_batch;
  /// residual = bc(ya, yb, p)  (residual has size n + k).
  std::function<void(ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef p, VectorRef residual)> bc;
  /// dfdy (n x n) and dfdp (n x k).
  std::function<void(double t, ConstVectorRef y, ConstVectorRef p, MatrixRef dfdy, MatrixRef dfdp)> rhs_jacobian;
  /// Optional, rhs_jacobian at many points in one call: columns n j .. n j + n - 1 of dfdy
  /// (n x n m) and k j .. k j + k - 1 of dfdp (n x k m) at (t[j], y.col(j), p). Used instead of
  /// rhs_jacobian when set; must agree with it.
  std::function<void(ConstVectorRef t, ConstMatrixRef y, ConstVectorRef p, MatrixRef dfdy, MatrixRef dfdp)>
      rhs_jacobian_batch;
  /// d bc / d ya, d bc / d yb ((n + k) x n) and d bc / dp ((n + k) x k).
  std::function<void(ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef p, MatrixRef dya, MatrixRef dyb,
                     MatrixRef dp)>
      bc_jacobian;
};

/// How the Newton matrix is factorised: the structured elimination of collocation_jacobian.hpp
/// (default; fast on small blocks) or Eigen's general SparseLU (COLAMD ordering). Same result.
enum class LinearSolverKind { BlockLU, SparseLU };

struct CollocationOptions {
  double tol = 1e-3;              ///< max relative RMS residual per interval (>= 100 eps)
  double bc_tol = 0;              ///< max |bc| (0: use tol)
  int max_nodes = 1000;           ///< mesh size limit
  int max_newton_iterations = 20; ///< Newton iterations on one mesh
  int max_refinements = 40;       ///< mesh refinement rounds
  double fd_step = 1.4901161193847656e-08;  ///< sqrt(eps): forward-difference relative step
  LinearSolverKind linear_solver = LinearSolverKind::BlockLU;
  /// Reuse the factorised Newton matrix while Newton contracts fast (chord steps); false: a
  /// fresh Jacobian every iteration. Same convergence test either way.
  bool reuse_jacobian = true;
  /// Progress (one report per Newton iteration) and stop requests (Status::Interrupted); may be null.
  const SolveMonitor* monitor = nullptr;

  /// Throws std::invalid_argument naming the bad option.
  void validate() const;
  double boundary_tolerance() const { return bc_tol > 0 ? bc_tol : tol; }
};

/// Outcomes (cartan/status.hpp): Converged (residual <= tol on every interval and |bc| <=
/// bc_tol), MaxNodesExceeded, SingularJacobian, NotConverged (Newton failed, refinement budget
/// exhausted, or f/bc not finite), Interrupted (options.monitor asked to stop).
struct BvpResult {
  Status status = Status::NotConverged;
  std::string message;
  Eigen::VectorXd t;             ///< final mesh (m nodes)
  Eigen::MatrixXd y;             ///< n x m solution at the nodes
  Eigen::MatrixXd yp;            ///< n x m f(t_i, y_i, p)
  Eigen::VectorXd p;             ///< unknown parameters
  Eigen::VectorXd rms_residual;  ///< relative RMS residual per interval (m - 1)
  double max_rms_residual = 0;
  double max_bc_residual = 0;
  int newton_iterations = 0;     ///< over all meshes
  int jacobian_evaluations = 0;
  int refinements = 0;           ///< meshes solved after the first
  int rhs_evaluations = 0;       ///< calls of f (finite differences included)

  bool success() const { return status == Status::Converged; }
  /// The solution's cubic interpolant (dense output).
  CubicHermite interpolant() const { return {t, y, yp}; }
  Eigen::VectorXd operator()(double time) const { return interpolant().value(time); }
};

/// Adaptive solve from the initial guess (mesh t, values y as n x m, parameters p).
/// Throws std::invalid_argument for bad input (non-finite values, a mesh that is not strictly
/// increasing, wrong dimensions, bad options).
BvpResult solve_collocation(const BvpSystem& system, const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                            const Eigen::VectorXd& p, const CollocationOptions& options = {});

/// Continuation: starts from a previous result's mesh, values and parameters (e.g. a solution
/// of a nearby problem or at a looser tolerance).
BvpResult solve_collocation(const BvpSystem& system, const BvpResult& previous, const CollocationOptions& options = {});

/// Solves the collocation equations on the given mesh only (no error control or refinement):
/// Success means Newton converged; rms_residual reports the accuracy. Used for order studies.
BvpResult solve_collocation_on_mesh(const BvpSystem& system, const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                                    const Eigen::VectorXd& p, const CollocationOptions& options = {});

}  // namespace cartan::numerics
