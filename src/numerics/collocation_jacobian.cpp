#include "cartan/numerics/collocation_jacobian.hpp"

#include <cmath>
#include <utility>

namespace cartan::numerics {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

void CollocationJacobian::resize(int states, int parameters, Index nodes) {
  n = states;
  k = parameters;
  m = nodes;
  A.resize(n, n * (m - 1));
  B.resize(n, n * (m - 1));
  C.resize(n, k * (m - 1));
  Da.resize(n + k, n);
  Db.resize(n + k, n);
  Dp.resize(n + k, k);
}

namespace {

void add_block(std::vector<Eigen::Triplet<double>>& triplets, Index row, Index col, const MatrixXd& block) {
  for (Index j = 0; j < block.cols(); ++j) {
    for (Index i = 0; i < block.rows(); ++i) triplets.emplace_back(row + i, col + j, block(i, j));
  }
}

}  // namespace

Eigen::SparseMatrix<double> CollocationJacobian::sparse() const {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(A.size() + B.size() + C.size() + Da.size() + Db.size() + Dp.size()));
  for (Index i = 0; i + 1 < m; ++i) {
    add_block(triplets, n * i, n * i, A.middleCols(n * i, n));
    add_block(triplets, n * i, n * (i + 1), B.middleCols(n * i, n));
    add_block(triplets, n * i, n * m, C.middleCols(k * i, k));
  }
  const Index bc_row = n * (m - 1);
  add_block(triplets, bc_row, 0, Da);
  add_block(triplets, bc_row, n * (m - 1), Db);
  add_block(triplets, bc_row, n * m, Dp);
  Eigen::SparseMatrix<double> out(n * m + k, n * m + k);
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

bool BlockLU::factorize(const CollocationJacobian& J) {
  n_ = J.n;
  k_ = J.k;
  const int n = n_, q = n_ + k_, width = 2 * n + q;  // panel columns: current | next | border (y_0, p)
  const Index steps = J.m - 1;
  steps_.resize(static_cast<std::size_t>(steps));
  error_.clear();
  // Rows carried into the next step: their coefficients of the current block and of the border.
  MatrixXd carry_current = J.B.leftCols(n), carry_border(n, q);
  carry_border << J.A.leftCols(n), J.C.leftCols(k_);
  for (Index j = 0; j < steps; ++j) {
    const bool last = j + 1 == steps;
    const Index fresh = last ? q : n;  // rows entering: r_{j+1}, or the boundary conditions
    Step& step = steps_[static_cast<std::size_t>(j)];
    MatrixXd& M = step.panel;
    M.setZero(n + fresh, width);
    M.topLeftCorner(n, n) = carry_current;
    M.topRightCorner(n, q) = carry_border;
    if (last) {
      M.bottomLeftCorner(q, n) = J.Db;
      M.bottomRightCorner(q, q) << J.Da, J.Dp;
    } else {
      M.bottomLeftCorner(n, n) = J.A.middleCols(n * (j + 1), n);
      M.block(n, n, n, n) = J.B.middleCols(n * (j + 1), n);
      M.bottomRightCorner(n, k_) = J.C.middleCols(k_ * (j + 1), k_);
    }
    // Unblocked partial pivoting on the n current columns (whole rows interchanged), each
    // elimination updating the whole rows: for these small panels (2n rows, up to 2n + q
    // columns) rank-one updates beat a blocked triangular solve and GEMM.
    step.swaps.resize(static_cast<std::size_t>(n));
    for (int c = 0; c < n; ++c) {
      Index pivot = c;
      M.col(c).tail(M.rows() - c).cwiseAbs().maxCoeff(&pivot);
      pivot += c;
      step.swaps[static_cast<std::size_t>(c)] = static_cast<int>(pivot);
      if (pivot != c) M.row(c).swap(M.row(pivot));
      const double diagonal = M(c, c);
      if (diagonal == 0 || !std::isfinite(diagonal)) {
        error_ = "zero pivot in block " + std::to_string(j + 1) + ", column " + std::to_string(c);
        return false;
      }
      const Index below = M.rows() - c - 1;
      M.col(c).tail(below) /= diagonal;
      // The rank-one update column by column, skipping the pivot row's zeros (a carried row has
      // none in the next block's columns, a fresh row none in the border's when k = 0).
      for (Index col = c + 1; col < width; ++col) {
        const double factor = M(c, col);
        if (factor != 0) M.col(col).tail(below) -= factor * M.col(c).tail(below);
      }
    }
    carry_current = M.bottomRows(fresh).middleCols(n, n);
    carry_border = M.bottomRightCorner(fresh, q);
  }
  border_.compute(carry_border);  // the q x q system for (y_0, p)
  if (!border_.isInvertible()) {
    error_ = "the reduced boundary system for (y(a), p) is singular (rank " + std::to_string(border_.rank()) + " of " +
             std::to_string(q) + ")";
    return false;
  }
  return true;
}

VectorXd BlockLU::solve(const VectorXd& rhs) const {
  const int n = n_, q = n_ + k_;
  const Index steps = static_cast<Index>(steps_.size());
  VectorXd pivot_rhs(n * steps);
  VectorXd b(2 * n + k_);
  b.head(n) = rhs.head(n);  // the rows carried into step 0: r_0
  for (Index j = 0; j < steps; ++j) {
    const Step& step = steps_[static_cast<std::size_t>(j)];
    const Index fresh = step.panel.rows() - n;
    b.segment(n, fresh) = rhs.segment(n * (j + 1), fresh);
    // The stored multipliers sit in their rows after all interchanges (as in LAPACK's getrf):
    // permute first, then eliminate.
    const Index rows = n + fresh;
    for (int c = 0; c < n; ++c) std::swap(b[c], b[step.swaps[static_cast<std::size_t>(c)]]);
    for (int c = 0; c < n; ++c) b.segment(c + 1, rows - c - 1) -= step.panel.col(c).tail(rows - c - 1) * b[c];
    pivot_rhs.segment(n * j, n) = b.head(n);
    for (Index i = 0; i < fresh; ++i) b[i] = b[n + i];  // carried rows (forward copy: no aliasing)
  }
  const VectorXd border = border_.solve(b.head(q));  // (y_0, p)
  VectorXd x(rhs.size());
  x.head(n) = border.head(n);
  x.tail(k_) = border.tail(k_);
  VectorXd next = VectorXd::Zero(n), right(n);
  for (Index j = steps - 1; j >= 0; --j) {
    const MatrixXd& U = steps_[static_cast<std::size_t>(j)].panel;
    right = pivot_rhs.segment(n * j, n);
    right.noalias() -= U.block(0, n, n, n) * next;
    right.noalias() -= U.topRightCorner(n, q) * border;
    U.topLeftCorner(n, n).triangularView<Eigen::Upper>().solveInPlace(right);
    next = right;
    x.segment(n * (j + 1), n) = next;
  }
  return x;
}

}  // namespace cartan::numerics
