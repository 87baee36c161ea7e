#pragma once
// Dense LU with partial pivoting, P A = L U (LAPACK's getrf, Eigen's PartialPivLU: the same
// pivots, the largest magnitude in each column), in place, blocked and right-looking, that can be
// stopped between pieces of work of bounded size.
//
// Each panel of kPanel columns is eliminated column by column; the trailing columns are then
// updated in chunks: the panel's row interchanges, U's rows by the panel's unit lower triangle
// (TRSM), and the trailing block minus the panel's multipliers times those rows (GEMM, 2 r kPanel w
// flops for r rows below the panel and w columns). The chunk width keeps a chunk's GEMM near
// kFlopsBetweenPolls, and `stop` is called after the panel and after every chunk: at the few
// GFLOP/s Eigen's product reaches here, a stop is seen within about 20 ms whatever the size.
// Eigen's own PartialPivLU updates the whole trailing matrix in one product (seconds for a few
// thousand unknowns) and cannot be stopped. Work (2/3) m^3 flops, storage the matrix itself.

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace cartan::numerics {

class BlockedLU {
 public:
  enum class Outcome { Factorized, Singular, Stopped };
  static constexpr Eigen::Index kPanel = 64;
  static constexpr double kFlopsBetweenPolls = 1e8;

  /// The square matrix to factorise: the caller writes it here (its storage is kept from one
  /// factorisation to the next), factorize() overwrites it with L (below the diagonal, unit
  /// diagonal implied) and U.
  Eigen::MatrixXd& matrix() { return lu_; }
  /// Factorises matrix() in place. `stop` (may be empty) is called between pieces of work (header
  /// comment); when it returns true the factorisation ends, Stopped, leaving matrix() neither A
  /// nor its factors. Singular: a pivot is zero or not finite (column: zero_pivot()).
  Outcome factorize(const std::function<bool()>& stop = {});
  /// x with A x = b, after a factorize() that returned Factorized.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// The column of the zero pivot after Singular, else -1.
  Eigen::Index zero_pivot() const { return zero_pivot_; }

 private:
  bool eliminate_panel(Eigen::Index first, Eigen::Index width);
  void swap_rows(Eigen::Index first, Eigen::Index width, Eigen::Index from, Eigen::Index to);

  Eigen::MatrixXd lu_;
  std::vector<Eigen::Index> swaps_;  ///< row i was interchanged with row swaps_[i] >= i, in order
  Eigen::Index zero_pivot_ = -1;
};

}  // namespace cartan::numerics
