#include "cartan/numerics/collocation_jacobian.hpp"

#include <cmath>
#include <type_traits>
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

namespace {

using Eigen::Dynamic;

/// Compile-time shapes of the panels for n states and q = n + k border columns (Dynamic: runtime).
template <int N, int Q>
struct PanelShape {
  static constexpr bool kFixed = N != Dynamic && Q != Dynamic;
  static constexpr int kRows = kFixed ? 2 * N : Dynamic;      ///< a panel before the last
  static constexpr int kLastRows = kFixed ? N + Q : Dynamic;  ///< the last panel (the bc rows)
  static constexpr int kWidth = kFixed ? 2 * N + Q : Dynamic;
  using Panel = Eigen::Matrix<double, kRows, kWidth>;
  using LastPanel = Eigen::Matrix<double, kLastRows, kWidth>;
};

/// Calls f with step j's panel (rows x width, column-major at data) mapped with its
/// compile-time shape: Panel before the last step, LastPanel at it.
template <int N, int Q, class Scalar, class F>
void with_panel(Scalar* data, bool last, Index rows, Index width, F&& f) {
  using S = PanelShape<N, Q>;
  using Panel = std::conditional_t<std::is_const_v<Scalar>, const typename S::Panel, typename S::Panel>;
  using LastPanel = std::conditional_t<std::is_const_v<Scalar>, const typename S::LastPanel, typename S::LastPanel>;
  if (last) {
    f(Eigen::Map<LastPanel>(data, rows, width));
  } else {
    f(Eigen::Map<Panel>(data, rows, width));
  }
}

/// Unblocked partial pivoting on the n current columns (whole rows interchanged), each
/// elimination updating the whole rows: for these small panels (2n rows, up to 2n + q columns)
/// rank-one updates beat a blocked triangular solve and GEMM. Returns the column of a zero or
/// non-finite pivot, or -1.
template <int N, class Panel>
int eliminate(Panel& M, int n, int* swaps) {
  constexpr int R = Panel::RowsAtCompileTime, W = Panel::ColsAtCompileTime;
  if constexpr (N != Dynamic && R != Dynamic && W != Dynamic) {
    // Fixed-size panel: every column's step unrolled, so that each rank-one update is a
    // compile-time-size outer product (column by column, as below; bit-identical: a zero factor
    // subtracts an exact zero).
    int failed = -1;
    auto column = [&]<int C>(std::integral_constant<int, C>) {
      constexpr int below = R - C - 1, right = W - C - 1;
      Index pivot = 0;
      M.col(C).template tail<R - C>().cwiseAbs().maxCoeff(&pivot);
      pivot += C;
      swaps[C] = static_cast<int>(pivot);
      if (pivot != C) M.row(C).swap(M.row(pivot));
      const double diagonal = M(C, C);
      if (diagonal == 0 || !std::isfinite(diagonal)) {
        failed = C;
        return false;
      }
      M.col(C).template tail<below>() /= diagonal;
      M.template bottomRightCorner<below, right>().noalias() -=
          M.col(C).template tail<below>() * M.row(C).template tail<right>();
      return true;
    };
    [&]<int... C>(std::integer_sequence<int, C...>) {
      (column(std::integral_constant<int, C>{}) && ...);
    }(std::make_integer_sequence<int, N>{});
    return failed;
  } else {
    const Index width = M.cols();
    for (int c = 0; c < n; ++c) {
      Index pivot = c;
      M.col(c).tail(M.rows() - c).cwiseAbs().maxCoeff(&pivot);
      pivot += c;
      swaps[c] = static_cast<int>(pivot);
      if (pivot != c) M.row(c).swap(M.row(pivot));
      const double diagonal = M(c, c);
      if (diagonal == 0 || !std::isfinite(diagonal)) return c;
      const Index below = M.rows() - c - 1;
      M.col(c).tail(below) /= diagonal;
      // The rank-one update column by column, skipping the pivot row's zeros (a carried row has
      // none in the next block's columns, a fresh row none in the border's when k = 0).
      for (Index col = c + 1; col < width; ++col) {
        const double factor = M(c, col);
        if (factor != 0) M.col(col).tail(below) -= factor * M.col(c).tail(below);
      }
    }
    return -1;
  }
}

/// The forward elimination of solve on one panel's multipliers: b(c+1:) -= M(c+1:, c) b_c.
template <int N, class Panel, class Vector>
void forward(const Panel& M, int n, Index rows, Vector& b) {
  constexpr int R = Panel::RowsAtCompileTime;
  if constexpr (N != Dynamic && R != Dynamic) {
    [&]<int... C>(std::integer_sequence<int, C...>) {
      ((b.template segment<R - C - 1>(C + 1) -= M.col(C).template tail<R - C - 1>() * b[C]), ...);
    }(std::make_integer_sequence<int, N>{});
  } else {
    for (int c = 0; c < n; ++c) b.segment(c + 1, rows - c - 1) -= M.col(c).tail(rows - c - 1) * b[c];
  }
}

}  // namespace

template <int N, int Q>
bool BlockLU::factorize_panels(const CollocationJacobian& J, const std::function<bool()>& stop) {
  const int n = n_, k = k_, q = n_ + k_, width = 2 * n + q;  // panel columns: current | next | border (y_0, p)
  const Index steps = steps_;
  const Index stride = Index{2} * n * width;  // doubles per panel before the last
  const Index size = stride * (steps - 1) + Index{n + q} * width;
  if (static_cast<std::size_t>(size) > panels_capacity_) {  // else keeps its storage
    panels_.reset();
    panels_ = std::make_unique_for_overwrite<double[]>(static_cast<std::size_t>(size));
    panels_capacity_ = static_cast<std::size_t>(size);
  }
  swaps_.resize(static_cast<std::size_t>(n * steps));
  const Index between_polls = steps_between_polls(n, k);
  for (Index j = 0; j < steps; ++j) {
    if (j % between_polls == between_polls - 1 && stop && stop()) {
      stopped_ = true;
      error_ = "stopped at block " + std::to_string(j) + " (time limit or cancellation)";
      return false;
    }
    const bool last = j + 1 == steps;
    const Index fresh = last ? q : n;  // rows entering: r_{j+1}, or the boundary conditions
    double* data = panels_.get() + stride * j;
    int failed = -1;
    with_panel<N, Q>(data, last, n + fresh, width, [&](auto M) {
      // Rows carried from the previous step: their coefficients of the current block and of the
      // border (the previous panel's fresh rows after its elimination; r_0 at the first step).
      if (j == 0) {
        M.topLeftCorner(n, n) = J.B.leftCols(n);
        M.topRightCorner(n, q) << J.A.leftCols(n), J.C.leftCols(k);
      } else {
        using S = PanelShape<N, Q>;
        const Eigen::Map<const typename S::Panel> previous(data - stride, 2 * n, width);
        M.topLeftCorner(n, n) = previous.bottomRows(n).middleCols(n, n);
        M.topRightCorner(n, q) = previous.bottomRightCorner(n, q);
      }
      M.block(0, n, n, n).setZero();
      if (last) {
        M.bottomLeftCorner(q, n) = J.Db;
        M.block(n, n, q, n).setZero();
        M.bottomRightCorner(q, q) << J.Da, J.Dp;
      } else {
        M.bottomLeftCorner(n, n) = J.A.middleCols(n * (j + 1), n);
        M.block(n, n, n, n) = J.B.middleCols(n * (j + 1), n);
        M.block(n, 2 * n, n, n).setZero();
        M.bottomRightCorner(n, k) = J.C.middleCols(k * (j + 1), k);
      }
      failed = eliminate<N>(M, n, swaps_.data() + n * j);
    });
    if (failed >= 0) {
      error_ = "zero pivot in block " + std::to_string(j + 1) + ", column " + std::to_string(failed);
      return false;
    }
  }
  // The q x q system for (y_0, p): the last panel's fresh rows in the border columns.
  const Eigen::Map<const MatrixXd> last(panels_.get() + stride * (steps - 1), n + q, width);
  border_.compute(last.bottomRightCorner(q, q));
  if (!border_.isInvertible()) {
    error_ = "the reduced boundary system for (y(a), p) is singular (rank " + std::to_string(border_.rank()) + " of " +
             std::to_string(q) + ")";
    return false;
  }
  return true;
}

template <int N, int Q>
VectorXd BlockLU::solve_panels(const VectorXd& rhs) const {
  using S = PanelShape<N, Q>;
  using Vector = Eigen::Matrix<double, N, 1>;
  const int n = n_, q = n_ + k_, width = 2 * n + q;
  const Index steps = steps_;
  const Index stride = Index{2} * n * width;
  pivot_rhs_.resize(n * steps);
  Eigen::Matrix<double, S::kLastRows, 1> b(n + q);
  b.head(n) = rhs.head(n);  // the rows carried into step 0: r_0
  for (Index j = 0; j < steps; ++j) {
    const bool last = j + 1 == steps;
    const Index fresh = last ? q : n;
    const Index rows = n + fresh;
    b.segment(n, fresh) = rhs.segment(n * (j + 1), fresh);
    const int* swaps = swaps_.data() + n * j;
    // The stored multipliers sit in their rows after all interchanges (as in LAPACK's getrf):
    // permute first, then eliminate.
    for (int c = 0; c < n; ++c) std::swap(b[c], b[swaps[c]]);
    with_panel<N, Q>(panels_.get() + stride * j, last, rows, width, [&](auto M) {
      forward<N>(M, n, rows, b);
    });
    pivot_rhs_.segment(n * j, n) = b.head(n);
    for (Index i = 0; i < fresh; ++i) b[i] = b[n + i];  // carried rows (forward copy: no aliasing)
  }
  const Eigen::Matrix<double, Q, 1> border = border_.solve(b.head(q));  // (y_0, p)
  VectorXd x(rhs.size());
  x.head(n) = border.head(n);
  x.tail(k_) = border.tail(k_);
  Vector next = Vector::Zero(n), right(n);
  for (Index j = steps - 1; j >= 0; --j) {
    with_panel<N, Q>(panels_.get() + stride * j, j + 1 == steps, n + (j + 1 == steps ? q : n), width, [&](auto U) {
      right = pivot_rhs_.segment(n * j, n);
      right.noalias() -= U.template block<N, N>(0, n, n, n) * next;
      right.noalias() -= U.template block<N, Q>(0, 2 * n, n, q) * border;
      U.template block<N, N>(0, 0, n, n).template triangularView<Eigen::Upper>().solveInPlace(right);
    });
    next = right;
    x.segment(n * (j + 1), n) = next;
  }
  return x;
}

namespace {

/// Calls f with the panels' compile-time shape (N, Q) = (n, n + k) where it is one of the fixed
/// paths, (Dynamic, Dynamic) otherwise: 2 states with or without one parameter (the small systems
/// of SciPy-style problems) and 6 (H3 in closed form). The generic transported systems (12 and 24
/// states) take the runtime path: unrolled, they cost 110 s of compile time for no measurable
/// gain at 12 states and 15 % of a factorisation at 24 (bench/README.md "Build time").
template <class F>
decltype(auto) with_panel_shape(int n, int q, F&& f) {
  using I2 = std::integral_constant<int, 2>;
  if (n == 2 && q == 2) return f(I2{}, I2{});
  if (n == 2 && q == 3) return f(I2{}, std::integral_constant<int, 3>{});
  if (n == 6 && q == 6) return f(std::integral_constant<int, 6>{}, std::integral_constant<int, 6>{});
  return f(std::integral_constant<int, Dynamic>{}, std::integral_constant<int, Dynamic>{});
}

}  // namespace

bool BlockLU::factorize(const CollocationJacobian& J, const std::function<bool()>& stop) {
  n_ = J.n;
  k_ = J.k;
  steps_ = J.m - 1;
  error_.clear();
  stopped_ = false;
  return with_panel_shape(n_, n_ + k_, [&](auto N, auto Q) {
    return factorize_panels<decltype(N)::value, decltype(Q)::value>(J, stop);
  });
}

VectorXd BlockLU::solve(const VectorXd& rhs) const {
  return with_panel_shape(n_, n_ + k_, [&](auto N, auto Q) { return solve_panels<decltype(N)::value, decltype(Q)::value>(rhs); });
}

}  // namespace cartan::numerics
