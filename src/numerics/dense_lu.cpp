// Blocked, stoppable dense LU with partial pivoting (numerics/dense_lu.hpp).
#include "cartan/numerics/dense_lu.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

#include "cartan/errors.hpp"

namespace cartan::numerics {

using Eigen::Index;

BlockedLU::Outcome BlockedLU::factorize(const std::function<bool()>& stop) {
  const Index m = lu_.rows();
  if (lu_.cols() != m) {
    throw_invalid("BlockedLU::factorize", "matrix()", std::to_string(m) + " x " + std::to_string(lu_.cols()),
                  "must be square");
  }
  swaps_.resize(static_cast<std::size_t>(m));
  zero_pivot_ = -1;
  const auto stopped = [&] { return stop && stop(); };
  for (Index first = 0; first < m; first += kPanel) {
    const Index width = std::min(kPanel, m - first), next = first + width, below = m - next;
    if (!eliminate_panel(first, width)) return Outcome::Singular;
    swap_rows(first, width, 0, first);  // the multipliers of the panels to the left
    if (stopped()) return Outcome::Stopped;
    const auto chunk = std::max(kPanel, static_cast<Index>(kFlopsBetweenPolls / (2.0 * double(below + 1) * double(width))));
    const auto lower = lu_.block(first, first, width, width).triangularView<Eigen::UnitLower>();
    for (Index column = next; column < m; column += chunk) {
      const Index columns = std::min(chunk, m - column);
      swap_rows(first, width, column, column + columns);
      auto u = lu_.block(first, column, width, columns);
      lower.solveInPlace(u);
      lu_.block(next, column, below, columns).noalias() -= lu_.block(next, first, below, width) * u;
      if (stopped()) return Outcome::Stopped;
    }
  }
  return Outcome::Factorized;
}

/// Columns first .. first + width - 1, rows from `first` down: unblocked elimination with the
/// panel's rows interchanged (the rest of each row later, swap_rows). False at a zero pivot.
bool BlockedLU::eliminate_panel(Index first, Index width) {
  const Index m = lu_.rows(), end = first + width;
  for (Index j = first; j < end; ++j) {
    Index pivot = 0;
    lu_.col(j).tail(m - j).cwiseAbs().maxCoeff(&pivot);
    pivot += j;
    swaps_[static_cast<std::size_t>(j)] = pivot;
    if (pivot != j) lu_.block(j, first, 1, width).swap(lu_.block(pivot, first, 1, width));
    const double diagonal = lu_(j, j);
    if (diagonal == 0 || !std::isfinite(diagonal)) {
      zero_pivot_ = j;
      return false;
    }
    const Index below = m - j - 1, right = end - j - 1;
    lu_.col(j).tail(below) /= diagonal;
    lu_.block(j + 1, j + 1, below, right).noalias() -= lu_.col(j).tail(below) * lu_.row(j).segment(j + 1, right);
  }
  return true;
}

/// The interchanges of rows first .. first + width - 1, in order, on the columns [from, to).
void BlockedLU::swap_rows(Index first, Index width, Index from, Index to) {
  for (Index column = from; column < to; ++column) {
    for (Index i = first; i < first + width; ++i) std::swap(lu_(i, column), lu_(swaps_[static_cast<std::size_t>(i)], column));
  }
}

Eigen::VectorXd BlockedLU::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  for (Index i = 0; i < x.size(); ++i) std::swap(x[i], x[swaps_[static_cast<std::size_t>(i)]]);
  lu_.triangularView<Eigen::UnitLower>().solveInPlace(x);
  lu_.triangularView<Eigen::Upper>().solveInPlace(x);
  return x;
}

}  // namespace cartan::numerics
