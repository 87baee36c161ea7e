#include "cartan/numerics/cubic_spline.hpp"

#include <cmath>
#include <string>

#include "cartan/errors.hpp"

namespace cartan::numerics {

namespace {

/// Solves the tridiagonal system with sub-diagonal dl (rows 1..m-1), diagonal d and
/// super-diagonal du (rows 0..m-2) for the rows of b (m x k), in place: Gaussian elimination with
/// partial pivoting (LAPACK's dgtsv), which fills a second super-diagonal where rows are swapped.
void solve_tridiagonal(Eigen::VectorXd dl, Eigen::VectorXd d, Eigen::VectorXd du, Eigen::MatrixXd& b) {
  const Eigen::Index m = d.size();
  Eigen::VectorXd du2 = Eigen::VectorXd::Zero(m);  // the fill-in of row i at column i + 2
  for (Eigen::Index i = 0; i + 1 < m; ++i) {
    // Rows i and i+1 now read: d_i x_i + du_i x_{i+1} (+ du2_i x_{i+2}) and dl_i x_i + d_{i+1} x_{i+1} + du_{i+1} x_{i+2}.
    if (std::abs(d[i]) >= std::abs(dl[i])) {
      const double factor = dl[i] / d[i];
      d[i + 1] -= factor * du[i];
      b.row(i + 1) -= factor * b.row(i);
    } else {  // swap rows i and i+1, then eliminate
      const double factor = d[i] / dl[i];
      d[i] = dl[i];
      const double old_diagonal = d[i + 1];
      d[i + 1] = du[i] - factor * old_diagonal;
      if (i + 2 < m) {
        du2[i] = du[i + 1];
        du[i + 1] = -factor * du2[i];
      }
      du[i] = old_diagonal;
      const Eigen::RowVectorXd row = b.row(i);
      b.row(i) = b.row(i + 1);
      b.row(i + 1) = row - factor * b.row(i);
    }
  }
  for (Eigen::Index i = m - 1; i >= 0; --i) {
    if (i + 1 < m) b.row(i) -= du[i] * b.row(i + 1);
    if (i + 2 < m) b.row(i) -= du2[i] * b.row(i + 2);
    b.row(i) /= d[i];
  }
}

}  // namespace

CubicHermite not_a_knot_spline(const Eigen::VectorXd& t, const Eigen::MatrixXd& y) {
  constexpr const char* where = "not_a_knot_spline";
  const Eigen::Index m = t.size();
  if (m < 2) throw_invalid(where, "t.size()", std::to_string(m), "must be at least 2");
  if (y.cols() != m) {
    throw_invalid(where, "y.cols()", std::to_string(y.cols()), "must equal t.size() = " + std::to_string(m) + " (one column per node)");
  }
  require_finite(t, where, "t");
  require_finite(y, where, "y");
  for (Eigen::Index i = 1; i < m; ++i) {
    if (!(t[i] > t[i - 1])) throw_invalid(where, "t[" + std::to_string(i) + "]", format_value(t[i]), "must be greater than t[i-1]");
  }
  const Eigen::VectorXd dx = t.tail(m - 1) - t.head(m - 1);
  Eigen::MatrixXd slope(m - 1, y.rows());  // d_i, one row per interval
  for (Eigen::Index i = 0; i + 1 < m; ++i) slope.row(i) = (y.col(i + 1) - y.col(i)).transpose() / dx[i];
  Eigen::MatrixXd s(m, y.rows());  // the slopes at the nodes, one row per node
  if (m == 2) {                    // the straight line
    s.row(0) = slope.row(0);
    s.row(1) = slope.row(0);
    return CubicHermite(t, y, s.transpose());
  }
  Eigen::VectorXd dl(m - 1), d(m), du(m - 1);
  if (m == 3) {  // the parabola: s_0 + s_1 = 2 d_0, s_1 + s_2 = 2 d_1 and the interior row
    d << 1, 2 * (dx[0] + dx[1]), 1;
    du << 1, dx[0];
    dl << dx[1], 1;
    s.row(0) = 2 * slope.row(0);
    s.row(1) = 3 * (dx[0] * slope.row(1) + dx[1] * slope.row(0));
    s.row(2) = 2 * slope.row(1);
  } else {
    for (Eigen::Index i = 1; i + 1 < m; ++i) {
      dl[i - 1] = dx[i];
      d[i] = 2 * (dx[i - 1] + dx[i]);
      du[i] = dx[i - 1];
      s.row(i) = 3 * (dx[i] * slope.row(i - 1) + dx[i - 1] * slope.row(i));
    }
    const double first = t[2] - t[0], last = t[m - 1] - t[m - 3];
    d[0] = dx[1];
    du[0] = first;
    s.row(0) = ((dx[0] + 2 * first) * dx[1] * slope.row(0) + dx[0] * dx[0] * slope.row(1)) / first;
    d[m - 1] = dx[m - 3];
    dl[m - 2] = last;
    s.row(m - 1) = (dx[m - 2] * dx[m - 2] * slope.row(m - 3) + (2 * last + dx[m - 2]) * dx[m - 3] * slope.row(m - 2)) / last;
  }
  solve_tridiagonal(dl, d, du, s);
  return CubicHermite(t, y, s.transpose());
}

}  // namespace cartan::numerics
