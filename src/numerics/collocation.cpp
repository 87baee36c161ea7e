#include "cartan/numerics/collocation.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "cartan/numerics/collocation_jacobian.hpp"
#include "cartan/errors.hpp"

namespace cartan::numerics {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using SparseSolver = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>;

constexpr std::string_view kWhere = "solve_collocation";
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
/// Newton stops when every collocation residual is below this fraction of tol h (1 + |f_mid|):
/// the midpoint residual of S is 1.5 r_i / h, so Newton's error is then <= 7.5% of tol ...
constexpr double kNewtonFraction = 0.05;
/// ... or at rounding level, this many ulps of the terms of r_i (needed when tol h is tiny).
constexpr double kRoundingUlps = 16;
constexpr int kMaxBacktracks = 10;
/// Newton reuses its factorisation for the next step after a full step whose simplified
/// correction shrank at least this much (the chord method then converges at least as fast).
constexpr double kReuseContraction = 0.25;
/// An interval with residual r > tol is split into ceil((r / tol)^(1/3)) pieces (the residual is
/// O(h^3)), at least 2 and at most this many per round (the model is only asymptotic).
constexpr int kMaxPieces = 6;

/// The user's functions with evaluation counts and forward-difference Jacobians.
class Model {
 public:
  /// `monitor` (may be null) is polled inside the difference Jacobians (rhs_jacobian).
  Model(const BvpSystem& system, double fd_step, const SolveMonitor* monitor)
      : s_(system), fd_step_(fd_step), monitor_(monitor) {}
  int n() const { return s_.n; }
  int k() const { return s_.k; }
  int evaluations() const { return evaluations_; }

  void rhs(double t, ConstVectorRef y, ConstVectorRef p, VectorRef out) {
    ++evaluations_;
    s_.rhs(t, y, p, out);
  }
  /// Column j of out (n x m, sized) = f(t[j], y.col(j), p): one call of rhs_batch when set (a
  /// user's vectorised f sees the whole mesh, as SciPy's does), else point by point with the
  /// monitor polled (polled_stop) when `pollable`. False when it polled a stop
  /// (out then holds NaN; stopped() is true).
  bool rhs(const VectorXd& t, const MatrixXd& y, const VectorXd& p, MatrixXd& out, bool pollable = true) {
    evaluations_ += static_cast<int>(t.size());
    if (s_.rhs_batch) {
      s_.rhs_batch(t, y, p, out);
      return true;
    }
    for (Index j = 0; j < t.size(); ++j) {
      if (pollable && polled_stop(j)) {
        out.setConstant(std::numeric_limits<double>::quiet_NaN());
        return false;
      }
      s_.rhs(t[j], y.col(j), p, out.col(j));
    }
    return true;
  }
  /// Whether a poll inside a sweep (rhs, rhs_jacobian, polled_stop) found a stop requested.
  bool stopped() const { return stopped_; }
  /// At point j of a sweep: whether the monitor asks to stop (then remembered: stopped()), polled
  /// at the points a PollPacer adapts to the sweep's pace, at most kPointsBetweenPolls apart (f in
  /// Python: a point can take a millisecond, and 256 of them were a quarter of a second past a limit).
  bool polled_stop(Index j) {
    if (stopped_ || !pacer_.due(j)) return stopped_;
    pacer_.polled();
    return stopped_ = SolveMonitor::poll(monitor_);
  }
  /// A poll now, between calls of a batched f (each a whole mesh).
  bool poll_now() { return stopped_ = stopped_ || SolveMonitor::poll(monitor_); }
  void bc(ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef p, VectorRef out) const { s_.bc(ya, yb, p, out); }

  /// df/dy (n x n m) and df/dp (n x k m) at the columns of y, where f0 = f(t, y, p) columnwise.
  /// False when the monitor polled a stop: at most every kPointsBetweenPolls points (a millisecond or two
  /// of differences), or between the components of the batched differences.
  bool rhs_jacobian(const VectorXd& t, const MatrixXd& y, const VectorXd& p, const MatrixXd& f0, MatrixXd& dfdy,
                    MatrixXd& dfdp) {
    const Index m = t.size();
    dfdy.resize(n(), n() * m);
    dfdp.resize(n(), k() * m);
    if (s_.rhs_jacobian_batch) {
      s_.rhs_jacobian_batch(t, y, p, dfdy, dfdp);
      return true;
    }
    if (!s_.rhs_jacobian && s_.rhs_batch) return batched_differences(t, y, p, f0, dfdy, dfdp);
    for (Index j = 0; j < m; ++j) {
      if (polled_stop(j)) return false;
      rhs_jacobian(t[j], y.col(j), p, f0.col(j), dfdy.middleCols(n() * j, n()), dfdp.middleCols(k() * j, k()));
    }
    return true;
  }
  static constexpr Index kPointsBetweenPolls = 256;

  /// d bc / d(ya, yb, p) at a point where bc = r0.
  void bc_jacobian(const VectorXd& ya, const VectorXd& yb, const VectorXd& p, const VectorXd& r0, MatrixXd& dya,
                   MatrixXd& dyb, MatrixXd& dp) const {
    const int rows = n() + k();
    dya.resize(rows, n());
    dyb.resize(rows, n());
    dp.resize(rows, k());
    if (s_.bc_jacobian) {
      s_.bc_jacobian(ya, yb, p, dya, dyb, dp);
      return;
    }
    VectorXd r(rows);
    difference(ya, dya, r0, [&](const VectorXd& x) { bc(x, yb, p, r); return r; });
    difference(yb, dyb, r0, [&](const VectorXd& x) { bc(ya, x, p, r); return r; });
    difference(p, dp, r0, [&](const VectorXd& x) { bc(ya, yb, x, r); return r; });
  }

 private:
  /// df/dy and df/dp at one point (t, y, p), where f0 = f(t, y, p).
  void rhs_jacobian(double t, ConstVectorRef y, ConstVectorRef p, ConstVectorRef f0, MatrixRef dfdy, MatrixRef dfdp) {
    if (s_.rhs_jacobian) {
      s_.rhs_jacobian(t, y, p, dfdy, dfdp);
      return;
    }
    VectorXd f(n());
    difference(y, dfdy, f0, [&](const VectorXd& yy) { rhs(t, yy, p, f); return f; });
    difference(p, dfdp, f0, [&](const VectorXd& pp) { rhs(t, y, pp, f); return f; });
  }

  /// The forward differences of the pointwise path below, every point at once: component i of y
  /// (then of p) is moved at all m points together, one rhs_batch call each (n + k calls instead of
  /// m (n + k)); the steps, and so the values, are those of the pointwise path.
  bool batched_differences(const VectorXd& t, const MatrixXd& y, const VectorXd& p, const MatrixXd& f0,
                           MatrixXd& dfdy, MatrixXd& dfdp) {
    const Index m = t.size();
    MatrixXd moved = y, f(n(), m);
    VectorXd step(m);
    for (Index i = 0; i < n(); ++i) {
      if (poll_now()) return false;
      for (Index j = 0; j < m; ++j) {
        moved(i, j) = moved_by_step(y(i, j));
        step[j] = moved(i, j) - y(i, j);
      }
      rhs(t, moved, p, f);
      for (Index j = 0; j < m; ++j) dfdy.col(n() * j + i) = (f.col(j) - f0.col(j)) / step[j];
      moved.row(i) = y.row(i);
    }
    VectorXd pp = p;
    for (Index i = 0; i < k(); ++i) {
      if (poll_now()) return false;
      pp[i] = moved_by_step(p[i]);
      const double dp = pp[i] - p[i];
      rhs(t, y, pp, f);
      for (Index j = 0; j < m; ++j) dfdp.col(k() * j + i) = (f.col(j) - f0.col(j)) / dp;
      pp[i] = p[i];
    }
    return true;
  }

  /// x moved by the difference step fd_step max(1, |x|), the same for every difference quotient.
  double moved_by_step(double x) const { return x + fd_step_ * std::max(1.0, std::abs(x)); }

  /// Forward differences of g at x (g(x) = g0), column j with step fd_step max(1, |x_j|).
  template <class Function>
  void difference(ConstVectorRef x, MatrixRef out, ConstVectorRef g0, const Function& g) const {
    VectorXd xx = x;
    for (Index j = 0; j < x.size(); ++j) {
      xx[j] = moved_by_step(x[j]);
      const double step = xx[j] - x[j];  // the step actually taken (exact in floating point)
      out.col(j) = (g(xx) - g0) / step;
      xx[j] = x[j];
    }
  }

  const BvpSystem& s_;
  double fd_step_;
  const SolveMonitor* monitor_;
  int evaluations_ = 0;
  bool stopped_ = false;
  PollPacer pacer_{kPointsBetweenPolls};  ///< polled_stop's points between polls
};

/// Column i of an n-row matrix, and the n x n block i of an n x n m one, with the compile-time
/// size N (Eigen::Dynamic: n at run time).
template <int N, class Matrix>
auto column(Matrix& x, Index i) {
  return x.template block<N, 1>(0, i, x.rows(), 1);
}
template <int N, class Matrix>
auto square(Matrix& x, Index i) {
  const Index n = x.rows();
  return x.template block<N, N>(0, n * i, n, n);
}

/// The collocation system at one iterate on one mesh.
struct Iterate {
  VectorXd t, h, tmid;  // nodes, steps, midpoints t_i + h_i / 2
  MatrixXd y, f;        // n x m
  MatrixXd ymid, fmid;  // n x (m - 1)
  VectorXd p;
  VectorXd residual;    // n (m - 1) collocation rows, then n + k boundary rows

  Index nodes() const { return t.size(); }
  VectorXd unknowns() const {
    VectorXd z(y.size() + p.size());
    z << y.reshaped(), p;
    return z;
  }
};

/// Evaluates f, the midpoint values and the residual; false if anything is not finite, or when
/// a sweep of f polled a stop (model.stopped(): f or fmid then hold NaN, never a stale value).
/// N: the state dimension at compile time (Eigen::Dynamic: model.n() at run time).
template <int N>
bool evaluate(Model& model, const VectorXd& t, const MatrixXd& y, const VectorXd& p, Iterate& it) {
  const int n = model.n();
  const Index m = t.size();
  it.t = t;
  it.h = t.tail(m - 1) - t.head(m - 1);
  it.tmid = t.head(m - 1) + it.h / 2;
  it.y = y;
  it.p = p;
  it.f.resize(n, m);
  it.ymid.resize(n, m - 1);
  it.fmid.resize(n, m - 1);
  it.residual.resize(n * m + model.k());
  const auto stopped = [&it] {
    it.residual.setConstant(std::numeric_limits<double>::quiet_NaN());
    return false;
  };
  if (!model.rhs(it.t, it.y, it.p, it.f)) return stopped();
  for (Index i = 0; i + 1 < m; ++i) {
    const double h = it.h[i];
    column<N>(it.ymid, i) =
        (column<N>(it.y, i) + column<N>(it.y, i + 1)) / 2 - h / 8 * (column<N>(it.f, i + 1) - column<N>(it.f, i));
  }
  if (!model.rhs(it.tmid, it.ymid, it.p, it.fmid)) return stopped();
  for (Index i = 0; i + 1 < m; ++i) {
    const double h = it.h[i];
    it.residual.template segment<N>(n * i, n) =
        column<N>(it.y, i + 1) - column<N>(it.y, i) -
        h / 6 * (column<N>(it.f, i) + 4 * column<N>(it.fmid, i) + column<N>(it.f, i + 1));
  }
  model.bc(it.y.col(0), it.y.col(m - 1), it.p, it.residual.tail(n + model.k()));
  return it.f.allFinite() && it.fmid.allFinite() && it.residual.allFinite();
}

template <int N>
bool evaluate(Model& model, const Iterate& shape, const VectorXd& z, Iterate& it) {
  const Index ny = shape.y.size();
  return evaluate<N>(model, shape.t, z.head(ny).reshaped(shape.y.rows(), shape.y.cols()), z.tail(z.size() - ny), it);
}

/// df/dy and df/dp at the nodes and at the midpoints of one iterate.
struct RateJacobians {
  MatrixXd dy_nodes, dp_nodes;  // n x n m, n x k m
  MatrixXd dy_mid, dp_mid;      // n x n (m - 1), n x k (m - 1)
};

/// The Jacobian of the residual with respect to (y_0, ..., y_{m-1}, p), blockwise; false when the
/// monitor polled a stop in the differences (Model::rhs_jacobian) or in the blocks' assembly (its
/// products cost about n^3 a block: 0.1 s at 8000 nodes of 24 states).
template <int N>
bool jacobian(Model& model, const Iterate& it, RateJacobians& rates, CollocationJacobian& jac) {
  using Square = Eigen::Matrix<double, N, N>;
  const int n = model.n(), k = model.k();
  const Index m = it.nodes();
  jac.resize(n, k, m);
  if (!model.rhs_jacobian(it.t, it.y, it.p, it.f, rates.dy_nodes, rates.dp_nodes) ||
      !model.rhs_jacobian(it.tmid, it.ymid, it.p, it.fmid, rates.dy_mid, rates.dp_mid)) {
    return false;
  }
  const Square eye = Square::Identity(n, n);
  for (Index i = 0; i + 1 < m; ++i) {
    if (model.polled_stop(i)) return false;
    const auto jy_left = square<N>(rates.dy_nodes, i), jy_right = square<N>(rates.dy_nodes, i + 1);
    const auto jmy = square<N>(rates.dy_mid, i);
    const double h = it.h[i];
    // dy_mid/dy_i = I/2 + h/8 J_i, dy_mid/dy_{i+1} = I/2 - h/8 J_{i+1}, dy_mid/dp = -h/8 (P_{i+1} - P_i).
    // lazyProduct: coefficient-wise products, much faster than GEMM for these small blocks.
    square<N>(jac.A, i) = -eye - h / 6 * jy_left - h / 3 * jmy - h * h / 12 * jmy.lazyProduct(jy_left);
    square<N>(jac.B, i) = eye - h / 6 * jy_right - h / 3 * jmy + h * h / 12 * jmy.lazyProduct(jy_right);
    if (k > 0) {
      const auto jp_left = rates.dp_nodes.middleCols(k * i, k), jp_right = rates.dp_nodes.middleCols(k * (i + 1), k);
      const auto jmp = rates.dp_mid.middleCols(k * i, k);
      jac.c(i) = -h / 6 * (jp_left + 4 * jmp + jp_right) + h * h / 12 * jmy * (jp_right - jp_left);
    }
  }
  model.bc_jacobian(it.y.col(0), it.y.col(m - 1), it.p, it.residual.tail(n + k), jac.Da, jac.Db, jac.Dp);
  return true;
}

/// Factorises the Newton matrix with the chosen solver and solves with it.
class LinearSolver {
 public:
  /// `block`: the block LU to use (the workspace's, whose storage outlives the solve).
  LinearSolver(LinearSolverKind kind, BlockLU& block) : kind_(kind), block_(block) {}
  /// False when the matrix is singular, or when the block LU polled a stop from `monitor` (stopped()).
  bool factorize(const CollocationJacobian& jac, const SolveMonitor* monitor) {
    if (kind_ == LinearSolverKind::BlockLU) {
      const bool ok = block_.factorize(jac, [monitor] { return SolveMonitor::poll(monitor); });
      error_ = block_.error();
      return ok;
    }
    const Eigen::SparseMatrix<double> sparse = jac.sparse();
    if (!analysed_) {  // the pattern depends on the mesh only: every block is stored in full
      sparse_.analyzePattern(sparse);
      analysed_ = true;
    }
    sparse_.factorize(sparse);
    error_ = sparse_.lastErrorMessage();
    return sparse_.info() == Eigen::Success;
  }
  VectorXd solve(const VectorXd& rhs) const {
    return kind_ == LinearSolverKind::BlockLU ? block_.solve(rhs) : VectorXd(sparse_.solve(rhs));
  }
  const std::string& error() const { return error_; }
  bool stopped() const { return kind_ == LinearSolverKind::BlockLU && block_.stopped(); }

 private:
  LinearSolverKind kind_;
  BlockLU& block_;
  SparseSolver sparse_;
  bool analysed_ = false;
  std::string error_;
};

/// The solver's working memory: the iterates, the Newton matrix, the block LU's panels and the
/// residual quadrature's points. Each thread keeps one across solves (WorkspaceLease), so that a
/// warm solve reuses memory already mapped instead of allocating it anew: glibc returns freed
/// blocks of this size to the system (trim, or munmap above the mmap threshold), and faulting
/// them in again took half of a small warm solve (bench/README.md, "Cold and warm"). Every
/// buffer is written before it is read, so results do not depend on what a previous solve left.
struct Workspace {
  Iterate it, trial;
  CollocationJacobian jac;
  RateJacobians rates;
  BlockLU block;
  VectorXd quadrature_times;                                  // rms_residuals' points ...
  MatrixXd quadrature_value, quadrature_slope, quadrature_f;  // ... S, S' and f there
  bool busy = false;  ///< in use by a solve on this thread

  /// Doubles held in the dense buffers.
  Index doubles() const {
    const auto iterate = [](const Iterate& x) {
      return x.t.size() + x.h.size() + x.tmid.size() + x.y.size() + x.f.size() + x.ymid.size() + x.fmid.size() +
             x.p.size() + x.residual.size();
    };
    return iterate(it) + iterate(trial) + jac.A.size() + jac.B.size() + jac.C.size() + rates.dy_nodes.size() +
           rates.dp_nodes.size() + rates.dy_mid.size() + rates.dp_mid.size() + block.storage() +
           quadrature_times.size() + quadrature_value.size() + quadrature_slope.size() + quadrature_f.size();
  }
};

/// A thread keeps at most this much working memory between solves; a larger workspace is
/// released after the solve (there the faults cost little next to the solve).
constexpr Index kMaxRetainedDoubles = Index{4} << 20;  // 32 MB

/// The calling thread's workspace for one solve: the thread's own, or, when that is already in
/// use (a solve called from a solve's callbacks on the same thread), a fresh one for this solve.
class WorkspaceLease {
 public:
  WorkspaceLease() {
    Workspace& shared = thread_workspace();
    if (shared.busy) {
      own_ = std::make_unique<Workspace>();
      workspace_ = own_.get();
    } else {
      shared.busy = true;
      workspace_ = &shared;
    }
  }
  ~WorkspaceLease() {
    if (own_) return;
    if (workspace_->doubles() > kMaxRetainedDoubles) *workspace_ = Workspace{};
    workspace_->busy = false;
  }
  WorkspaceLease(const WorkspaceLease&) = delete;
  WorkspaceLease& operator=(const WorkspaceLease&) = delete;
  Workspace& get() const { return *workspace_; }

 private:
  static Workspace& thread_workspace() {
    thread_local Workspace workspace;
    return workspace;
  }
  std::unique_ptr<Workspace> own_;
  Workspace* workspace_ = nullptr;
};

/// Largest collocation residual relative to its Newton target, and largest |bc|.
struct ResidualSize {
  double collocation = 0;  // max |r_ij| / target_ij; Newton needs <= 1
  double boundary = 0;
};

ResidualSize residual_size(const Iterate& it, int n, double tol) {
  ResidualSize size;
  for (Index i = 0; i + 1 < it.nodes(); ++i) {
    const double h = it.h[i];
    const auto fmid = it.fmid.col(i).array().abs();
    const auto terms = it.y.col(i).array().abs() + it.y.col(i + 1).array().abs() +
                       h * (it.f.col(i).array().abs() + 4 * fmid + it.f.col(i + 1).array().abs()) / 6;
    const auto target = (kNewtonFraction * tol * h * (1 + fmid)).max(kRoundingUlps * kEpsilon * terms);
    size.collocation = std::max(size.collocation, (it.residual.segment(n * i, n).array().abs() / target).maxCoeff());
  }
  size.boundary = it.residual.tail(it.residual.size() - n * (it.nodes() - 1)).cwiseAbs().maxCoeff();
  return size;
}

struct NewtonOutcome {
  Status status = Status::Converged;
  std::string message;
};

struct Counters {
  int newton = 0;
  int jacobians = 0;
};

bool newton_converged(const ResidualSize& size, const CollocationOptions& options) {
  return size.collocation <= 1 && size.boundary <= options.boundary_tolerance();
}

std::string describe(const ResidualSize& size, const CollocationOptions& options) {
  std::ostringstream out;
  out << "max collocation residual " << format_value(size.collocation) << " x its target "
      << format_value(kNewtonFraction * options.tol) << " h (1 + |f|), max |bc| " << format_value(size.boundary)
      << " (bc_tol " << format_value(options.boundary_tolerance()) << ")";
  return out.str();
}

/// Damped Newton from `it` (evaluated); on return `it` holds the last accepted iterate. A trial
/// step alpha is accepted when the simplified Newton correction |J^{-1} r(z - alpha dz)| is at
/// most (1 - alpha/4) |dz| (natural monotonicity, affine invariant) or the trial has converged.
/// Jacobian reuse: after a full step (alpha = 1) that contracted well, theta = |simplified| / |dz|
/// <= kReuseContraction, the simplified correction already computed with the old factorisation
/// is the next step (a chord step, as in Deuflhard's NLEQ codes and COLNEW). A chord step is
/// only taken in full; when it is not accepted, the iteration starts again from a fresh
/// Jacobian at the same iterate.
/// `from_guess`: `it` is the caller's guess (not a previous solution, nor a given mesh), and Newton
/// takes at least one step from it, as SciPy's solve_newton does on every mesh: a guess that meets
/// the target's absolute floor (the 1 of 1 + |f|) is no solution on the problem's own scale (SO(3),
/// a rotation of 1e-6: xi ~ 1e-13 was left at its guess 0, and verify's residual on xi' was 0.25).
template <int N>
NewtonOutcome newton(Model& model, Workspace& workspace, const CollocationOptions& options, Counters& counters,
                     bool from_guess) {
  const int n = model.n();
  LinearSolver solver(options.linear_solver, workspace.block);
  CollocationJacobian& jac = workspace.jac;
  RateJacobians& rates = workspace.rates;
  Iterate& it = workspace.it;
  Iterate& trial = workspace.trial;
  VectorXd chord;  // the next step with the current factorisation, when reusing it
  bool reuse = false;
  // One acceptance test and one reuse test for Newton and chord steps alike.
  auto acceptable = [&](double simplified, double norm, double alpha) {
    return simplified <= (1 - alpha / 4) * norm || newton_converged(residual_size(trial, n, options.tol), options);
  };
  auto worth_reusing = [&](double simplified, double norm) {
    return options.reuse_jacobian && simplified <= kReuseContraction * norm;
  };
  // Inside the phases of an iteration (the Jacobian's differences, the factorisation) and between
  // them (each trial): a stop abandons the iteration and returns the last accepted iterate, `it`.
  auto poll = [&] { return SolveMonitor::poll(options.monitor); };
  const NewtonOutcome stopped{Status::Interrupted, "stop requested"};
  for (int iteration = 0;; ++iteration) {
    const ResidualSize size = residual_size(it, n, options.tol);
    if ((iteration > 0 || !from_guess) && newton_converged(size, options)) return {};
    if (iteration == options.max_newton_iterations) {
      return {Status::NotConverged, "Newton did not converge in " + std::to_string(iteration) +
                                           " iterations on " + std::to_string(it.nodes()) + " nodes: " +
                                           describe(size, options)};
    }
    if (options.monitor != nullptr) {
      options.monitor->report(counters.newton, std::max(size.collocation, size.boundary));
      if (options.monitor->stop_requested()) return stopped;
    }
    ++counters.newton;
    const VectorXd z = it.unknowns();
    if (reuse) {
      reuse = false;
      const double norm = chord.norm();
      const bool evaluated = evaluate<N>(model, it, VectorXd(z - chord), trial);
      if (model.stopped()) return stopped;
      if (evaluated) {
        VectorXd next = solver.solve(trial.residual);
        const double simplified = next.norm();
        if (acceptable(simplified, norm, 1)) {
          reuse = worth_reusing(simplified, norm);
          chord = std::move(next);
          std::swap(it, trial);
          continue;
        }
      }
    }
    if (!jacobian<N>(model, it, rates, jac)) return stopped;
    ++counters.jacobians;
    if (poll()) return stopped;
    if (!solver.factorize(jac, options.monitor)) {
      if (solver.stopped()) return stopped;
      return {Status::SingularJacobian, "the collocation Jacobian is singular on " + std::to_string(it.nodes()) +
                                               " nodes (" + solver.error() + ")"};
    }
    const VectorXd step = solver.solve(it.residual);
    if (!step.allFinite()) {
      return {Status::SingularJacobian,
              "the Newton step is not finite on " + std::to_string(it.nodes()) + " nodes (singular Jacobian)"};
    }
    const double norm = step.norm();
    double alpha = 1;
    bool accepted = false;
    for (int backtrack = 0; backtrack < kMaxBacktracks && !accepted; ++backtrack, alpha /= 2) {
      if (poll()) return stopped;
      if (!evaluate<N>(model, it, VectorXd(z - alpha * step), trial)) {
        if (model.stopped()) return stopped;
        continue;
      }
      chord = solver.solve(trial.residual);
      const double simplified = chord.norm();
      accepted = acceptable(simplified, norm, alpha);
      reuse = accepted && alpha == 1 && worth_reusing(simplified, norm);
    }
    if (!accepted) {
      return {Status::NotConverged, "Newton's line search failed after " + std::to_string(kMaxBacktracks) +
                                           " halvings on " + std::to_string(it.nodes()) + " nodes: " +
                                           describe(size, options)};
    }
    std::swap(it, trial);
  }
}

/// Relative RMS residual of the cubic interpolant on each interval. rho = (S' - f(t, S)) / (1 + |f|)
/// is integrated by 5-point Lobatto quadrature (nodes 0, 1/2 -+ sqrt(3/7)/2, 1 in units of h;
/// weights 1/20, 49/180, 16/45, 49/180, 1/20); rho = 0 at the nodes, where S' = f. The cubic S on
/// interval i (CubicHermite's formulas, without its search for the interval) is evaluated at
/// both inner points of every interval first, then f at all of them in one sweep.
template <int N>
VectorXd rms_residuals(Model& model, Workspace& workspace) {
  using Vector = Eigen::Matrix<double, N, 1>;
  const Iterate& it = workspace.it;
  const int n = model.n();
  const Index intervals = it.nodes() - 1;
  const double offset = std::sqrt(3.0 / 7.0) / 2;
  VectorXd& times = workspace.quadrature_times;
  MatrixXd& value = workspace.quadrature_value;
  MatrixXd& slope = workspace.quadrature_slope;
  MatrixXd& f = workspace.quadrature_f;
  times.resize(2 * intervals);
  value.resize(n, 2 * intervals);
  slope.resize(n, 2 * intervals);
  f.resize(n, 2 * intervals);
  for (Index i = 0; i < intervals; ++i) {
    const double h = it.h[i], mid = it.t[i] + h / 2;
    const auto y0 = column<N>(it.y, i), y1 = column<N>(it.y, i + 1);
    const auto f0 = column<N>(it.f, i), f1 = column<N>(it.f, i + 1);
    for (int side = 0; side < 2; ++side) {
      const double tt = side == 0 ? mid - offset * h : mid + offset * h;
      const double s = (tt - it.t[i]) / h;
      const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
      const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
      const double d00 = 6 * s * (s - 1), d10 = (1 - s) * (1 - 3 * s);
      const double d01 = -d00, d11 = s * (3 * s - 2);
      times[2 * i + side] = tt;
      column<N>(value, 2 * i + side) = h00 * y0 + h * h10 * f0 + h01 * y1 + h * h11 * f1;
      column<N>(slope, 2 * i + side) = (d00 * y0 + d01 * y1) / h + d10 * f0 + d11 * f1;
    }
  }
  model.rhs(times, value, it.p, f, /*pollable=*/false);  // the result's diagnostics, once a Newton iteration ended
  auto relative = [](const auto& dS, const auto& rate) {
    return ((dS - rate).array() / (1 + rate.array().abs())).matrix().squaredNorm();
  };
  VectorXd rms(intervals);
  for (Index i = 0; i < intervals; ++i) {
    const double h = it.h[i], mid = it.t[i] + h / 2;
    const double s = (mid - it.t[i]) / h;  // S' at the midpoint
    const double d00 = 6 * s * (s - 1), d10 = (1 - s) * (1 - 3 * s);
    const double d01 = -d00, d11 = s * (3 * s - 2);
    const Vector mid_slope = (d00 * column<N>(it.y, i) + d01 * column<N>(it.y, i + 1)) / h +
                             d10 * column<N>(it.f, i) + d11 * column<N>(it.f, i + 1);
    const double outer =
        relative(column<N>(slope, 2 * i), column<N>(f, 2 * i)) + relative(column<N>(slope, 2 * i + 1), column<N>(f, 2 * i + 1));
    rms[i] = std::sqrt(49.0 / 180.0 * outer + 16.0 / 45.0 * relative(mid_slope, column<N>(it.fmid, i)));
  }
  return rms;
}

/// New mesh: interval i is split into `pieces[i]` equal parts; values from the interpolant.
void refine(const Iterate& it, const std::vector<int>& pieces, VectorXd& t, MatrixXd& y) {
  const CubicHermite s(it.t, it.y, it.f);
  std::vector<double> nodes{it.t[0]};
  for (Index i = 0; i + 1 < it.nodes(); ++i) {
    const int parts = pieces[static_cast<std::size_t>(i)];
    for (int j = 1; j < parts; ++j) nodes.push_back(it.t[i] + it.h[i] * j / parts);
    nodes.push_back(it.t[i + 1]);
  }
  t = Eigen::Map<const VectorXd>(nodes.data(), static_cast<Index>(nodes.size()));
  y = s.values(t);
}

/// The result from the last iterate; `rms`: its residuals when already computed (null: computed here).
template <int N>
void fill(BvpResult& result, Model& model, Workspace& workspace, const Counters& counters, Status status,
          const std::string& message, const VectorXd* rms = nullptr) {
  const Iterate& it = workspace.it;
  result.status = status;
  result.t = it.t;
  result.y = it.y;
  result.yp = it.f;
  result.p = it.p;
  result.newton_iterations = counters.newton;
  result.jacobian_evaluations = counters.jacobians;
  if (rms != nullptr) {
    result.rms_residual = *rms;
    result.max_rms_residual = result.rms_residual.maxCoeff();
  } else if (status != Status::Interrupted && it.f.allFinite() && it.fmid.allFinite()) {
    // Not after a stop: with f in Python, 2 evaluations an interval took 0.2 s past a time limit.
    result.rms_residual = rms_residuals<N>(model, workspace);
    result.max_rms_residual = result.rms_residual.maxCoeff();
  } else {
    result.max_rms_residual = std::numeric_limits<double>::quiet_NaN();  // not computed, never a 0
  }
  result.max_bc_residual = it.residual.tail(model.n() + model.k()).cwiseAbs().maxCoeff();
  result.rhs_evaluations = model.evaluations();
  std::ostringstream out;
  out << to_string(status) << ": " << message << " (" << it.nodes() << " nodes, " << result.refinements
      << " refinements, " << counters.newton << " Newton iterations, max relative residual "
      << format_value(result.max_rms_residual) << ", max |bc| " << format_value(result.max_bc_residual) << ")";
  result.message = out.str();
}

void validate_input(const BvpSystem& system, const VectorXd& t, const MatrixXd& y, const VectorXd& p,
                    const CollocationOptions& options) {
  options.validate();
  if (system.n < 1) throw_invalid(kWhere, "system.n", std::to_string(system.n), "must be at least 1");
  if (system.k < 0) throw_invalid(kWhere, "system.k", std::to_string(system.k), "must be non-negative");
  if (!system.rhs) throw_invalid(kWhere, "system.rhs", "(empty)", "must be set");
  if (!system.bc) throw_invalid(kWhere, "system.bc", "(empty)", "must be set");
  if (t.size() < 2) throw_invalid(kWhere, "t", format_value(t.transpose()), "must have at least 2 nodes");
  require_finite(t, kWhere, "t");
  for (Index i = 0; i + 1 < t.size(); ++i) {
    if (!(t[i + 1] > t[i])) {
      throw_invalid(kWhere, "t", format_value(t.transpose()),
                    "is not strictly increasing: t[" + std::to_string(i + 1) + "] = " + format_value(t[i + 1]) +
                        " <= t[" + std::to_string(i) + "] = " + format_value(t[i]));
    }
  }
  if (t.size() > options.max_nodes) {
    throw_invalid(kWhere, "t", "(" + std::to_string(t.size()) + " nodes)",
                  "has more nodes than options.max_nodes = " + std::to_string(options.max_nodes));
  }
  require_shape(y, system.n, t.size(), kWhere, "y");
  require_finite(y, kWhere, "y");
  require_shape(p, system.k, 1, kWhere, "p");
  require_finite(p, kWhere, "p");
}

template <int N>
BvpResult run(const BvpSystem& system, VectorXd t, MatrixXd y, const VectorXd& p, const CollocationOptions& options,
              bool adapt, bool from_guess) {
  Model model(system, options.fd_step, options.monitor);
  Counters counters;
  BvpResult result;
  const WorkspaceLease lease;
  Workspace& workspace = lease.get();
  Iterate& it = workspace.it;
  for (int round = 0;; ++round) {
    result.refinements = round;
    const VectorXd params = round == 0 ? p : it.p;
    if (!evaluate<N>(model, t, y, params, it)) {
      const std::string where = round == 0 ? "initial guess" : "refined mesh's start";
      if (model.stopped()) {
        fill<N>(result, model, workspace, counters, Status::Interrupted, "stop requested while evaluating the " + where);
      } else {
        fill<N>(result, model, workspace, counters, Status::NotConverged, "f or bc is not finite at the " + where);
      }
      return result;
    }
    const NewtonOutcome outcome = newton<N>(model, workspace, options, counters, from_guess && round == 0);
    if (outcome.status == Status::SingularJacobian || outcome.status == Status::Interrupted ||
        (outcome.status != Status::Converged && !adapt)) {
      fill<N>(result, model, workspace, counters, outcome.status, outcome.message);
      return result;
    }
    const Index m = it.nodes();
    std::vector<int> pieces(static_cast<std::size_t>(m - 1), 2);  // after a Newton failure: halve all
    std::string why = outcome.message;
    VectorXd rms;
    if (outcome.status == Status::Converged) {
      if (!adapt) {
        fill<N>(result, model, workspace, counters, Status::Converged, "collocation equations solved on the given mesh");
        return result;
      }
      rms = rms_residuals<N>(model, workspace);
      if (rms.maxCoeff() <= options.tol) {
        fill<N>(result, model, workspace, counters, Status::Converged, "residual below tol = " + format_value(options.tol), &rms);
        return result;
      }
      for (Index i = 0; i + 1 < m; ++i) {
        const double r = rms[i];
        pieces[static_cast<std::size_t>(i)] =
            r <= options.tol ? 1 : std::clamp(static_cast<int>(std::ceil(std::cbrt(r / options.tol))), 2, kMaxPieces);
      }
      why = "residual " + format_value(rms.maxCoeff()) + " above tol = " + format_value(options.tol);
    }
    Index needed = 1;
    for (int parts : pieces) needed += parts;
    if (needed > options.max_nodes) {
      const Status status =
          outcome.status == Status::Converged ? Status::MaxNodesExceeded : Status::NotConverged;
      fill<N>(result, model, workspace, counters, status,
           why + "; refining needs " + std::to_string(needed) + " nodes > max_nodes = " +
               std::to_string(options.max_nodes));
      return result;
    }
    if (round == options.max_refinements) {
      fill<N>(result, model, workspace, counters, Status::NotConverged,
           why + " after max_refinements = " + std::to_string(options.max_refinements));
      return result;
    }
    if (SolveMonitor::poll(options.monitor)) {  // before the refined mesh's interpolation and first evaluation
      fill<N>(result, model, workspace, counters, Status::Interrupted, "stop requested before refining",
              rms.size() > 0 ? &rms : nullptr);
      return result;
    }
    refine(it, pieces, t, y);
  }
}

/// The solve with the state dimension fixed at compile time where it is one of the transported
/// systems' (6: H3 in closed form; 12, 24: the generic form on H3 and SO(3)) or 2 (second-order
/// scalar problems, the commonest in SciPy-style use), so that the per-interval blocks have fixed
/// sizes; any other n at run time.
BvpResult dispatch(const BvpSystem& system, const VectorXd& t, const MatrixXd& y, const VectorXd& p,
                   const CollocationOptions& options, bool adapt, bool from_guess) {
  validate_input(system, t, y, p, options);
  switch (system.n) {
    case 2: return run<2>(system, t, y, p, options, adapt, from_guess);
    case 6: return run<6>(system, t, y, p, options, adapt, from_guess);
    case 12: return run<12>(system, t, y, p, options, adapt, from_guess);
    case 24: return run<24>(system, t, y, p, options, adapt, from_guess);
    default: return run<Eigen::Dynamic>(system, t, y, p, options, adapt, from_guess);
  }
}

}  // namespace

void CollocationOptions::validate() const {
  constexpr std::string_view where = "CollocationOptions";
  require_finite(tol, where, "tol");
  require_reachable_tolerance(tol, where);
  require_finite(bc_tol, where, "bc_tol");
  if (bc_tol < 0) throw_invalid(where, "bc_tol", format_value(bc_tol), "must be non-negative (0: use tol)");
  if (max_nodes < 2) throw_invalid(where, "max_nodes", std::to_string(max_nodes), "must be at least 2");
  if (max_newton_iterations < 1) {
    throw_invalid(where, "max_newton_iterations", std::to_string(max_newton_iterations), "must be at least 1");
  }
  if (max_refinements < 0) {
    throw_invalid(where, "max_refinements", std::to_string(max_refinements), "must be non-negative");
  }
  require_finite(fd_step, where, "fd_step");
  if (!(fd_step > 0)) throw_invalid(where, "fd_step", format_value(fd_step), "must be positive");
}

BvpResult solve_collocation(const BvpSystem& system, const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                            const Eigen::VectorXd& p, const CollocationOptions& options) {
  return dispatch(system, t, y, p, options, true, true);
}

BvpResult solve_collocation(const BvpSystem& system, const BvpResult& previous, const CollocationOptions& options) {
  return dispatch(system, previous.t, previous.y, previous.p, options, true, false);  // a solution, not a guess
}

BvpResult solve_collocation_on_mesh(const BvpSystem& system, const Eigen::VectorXd& t, const Eigen::MatrixXd& y,
                                    const Eigen::VectorXd& p, const CollocationOptions& options) {
  return dispatch(system, t, y, p, options, false, false);
}

}  // namespace cartan::numerics
