#pragma once
// The Newton matrix of the collocation equations (numerics/collocation.hpp) and its two solvers.
//
// Rows: the collocation residuals r_0 .. r_{m-2} (n each), then the n + k boundary conditions;
// unknowns: y_0 .. y_{m-1} (n each), then p (k). Row block i touches only y_i (block A_i),
// y_{i+1} (B_i) and p (C_i); the boundary rows touch y_0 (Da), y_{m-1} (Db) and p (Dp).
//
// BlockLU is Gaussian elimination with partial pivoting on this matrix with the unknowns
// ordered (y_1, ..., y_{m-1} | y_0, p): every column of y_{j+1} has non-zeros only in the n rows
// left over from the previous step and in the next row block, so each step factorises a
// 2n x n panel (n + (n + k) rows at the last), pivoting among exactly the rows a general sparse
// LU with partial pivoting would consider. What is left is a dense (n + k) x (n + k) system for
// (y_0, p). Work and storage are O(m n^2 (n + k)); the result equals Eigen's SparseLU up to
// rounding (tests/numerics/test_collocation_jacobian.cpp), without its per-factorisation overhead on small blocks.
// Where the block size is small and known (n = 6, k = 0: the closed-form H3 system; n = 2,
// k <= 1) the panels have compile-time shapes and each column's elimination is unrolled: the
// same factors, bit for bit, in fewer instructions (bench/README.md, "Collocation").

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cartan::numerics {

struct CollocationJacobian {
  int n = 0, k = 0;
  Eigen::Index m = 0;         ///< mesh nodes
  Eigen::MatrixXd A, B;       ///< n x n(m-1): block i is d r_i / d y_i, d r_i / d y_{i+1}
  Eigen::MatrixXd C;          ///< n x k(m-1): block i is d r_i / d p
  Eigen::MatrixXd Da, Db, Dp; ///< (n+k) x n, (n+k) x n, (n+k) x k: d bc / d(y_0, y_{m-1}, p)

  void resize(int states, int parameters, Eigen::Index nodes);
  auto a(Eigen::Index i) { return A.middleCols(n * i, n); }
  auto b(Eigen::Index i) { return B.middleCols(n * i, n); }
  auto c(Eigen::Index i) { return C.middleCols(k * i, k); }
  /// The same matrix in compressed sparse form (for Eigen's SparseLU).
  Eigen::SparseMatrix<double> sparse() const;
};

class BlockLU {
 public:
  /// Returns false (and sets error()) when a pivot is zero or not finite, or when `stop` (may be
  /// empty; called every steps_between_polls(n, k) steps) returns true (stopped()).
  bool factorize(const CollocationJacobian& jacobian, const std::function<bool()>& stop = {});
  bool stopped() const { return stopped_; }
  /// The multiply-adds of elimination between two polls of `stop`: about a tenth of a millisecond.
  static constexpr Eigen::Index kMultiplyAddsBetweenPolls = Eigen::Index{1} << 18;
  /// The steps between two polls for n states and k parameters: a step eliminates n columns of a
  /// 2n x (3n + k) panel, about n^2 (3n + k) multiply-adds (one step of 24 states: 0.05-0.1 ms,
  /// so a count fixed for 2 states would poll every 25 ms there).
  static Eigen::Index steps_between_polls(int n, int k) {
    const Eigen::Index per_step = Eigen::Index{n} * n * (3 * Eigen::Index{n} + k);
    return std::max<Eigen::Index>(1, kMultiplyAddsBetweenPolls / std::max<Eigen::Index>(1, per_step));
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  const std::string& error() const { return error_; }
  /// Doubles held by the factors (their storage is kept when a smaller matrix is factorised next,
  /// so that a solver reusing this object does not allocate again).
  Eigen::Index storage() const {
    return static_cast<Eigen::Index>(panels_capacity_ + swaps_.capacity() / 2) + pivot_rhs_.size();
  }

 private:
  // The panels' shapes are compile-time constants for a few (n, k) (collocation_jacobian.cpp:
  // with_panel_shape, e.g. the six states of the closed-form H3 system, or two states and at most
  // one parameter): the same elimination, in the same order, on fixed-size panels. Other sizes
  // take the runtime-size path.
  template <int N, int Q>
  bool factorize_panels(const CollocationJacobian& jacobian, const std::function<bool()>& stop);
  template <int N, int Q>
  Eigen::VectorXd solve_panels(const Eigen::VectorXd& rhs) const;

  int n_ = 0, k_ = 0;
  Eigen::Index steps_ = 0;
  /// The panels after elimination, one after the other (column-major; steps_ - 1 of 2n rows, the
  /// last n + q): multipliers (left n columns, below the diagonal), U (top n rows:
  /// current | next | border).
  /// Allocated, never initialised: factorize writes every entry of a panel before it reads it,
  /// so its memory is first touched by the elimination, which polls its stop (zeroing 440 MB of
  /// panels for 16 000 steps of 24 states took 0.5 s before the first poll).
  std::unique_ptr<double[]> panels_;
  std::size_t panels_capacity_ = 0;  ///< doubles allocated (kept when a smaller matrix comes next)
  std::vector<int> swaps_;         ///< row interchanges, n per step, in order
  Eigen::FullPivLU<Eigen::MatrixXd> border_;
  mutable Eigen::VectorXd pivot_rhs_;  ///< solve's workspace
  std::string error_;
  bool stopped_ = false;
};

}  // namespace cartan::numerics
