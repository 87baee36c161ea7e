#pragma once
// The not-a-knot cubic spline through (t_i, y_i): the C^2 piecewise cubic whose third derivative
// is continuous at t_1 and t_{m-2} (SciPy's CubicSpline default, de Boor, "A Practical Guide to
// Splines", ch. IV). Its slopes solve a tridiagonal system (below), here by Gaussian elimination
// with partial pivoting (LAPACK's dgtsv): the not-a-knot rows are not diagonally dominant. Two
// nodes give the straight line, three the parabola through them. The spline is returned as the
// cubic Hermite interpolant with those slopes (cubic_hermite.hpp). It reproduces cubics exactly.
//
// Slopes s_i (dx_i = t_{i+1} - t_i, d_i = (y_{i+1} - y_i) / dx_i), interior rows 0 < i < m-1:
//   dx_i s_{i-1} + 2 (dx_{i-1} + dx_i) s_i + dx_{i-1} s_{i+1} = 3 (dx_i d_{i-1} + dx_{i-1} d_i);
// first row: dx_1 s_0 + (t_2 - t_0) s_1 = ((dx_0 + 2 (t_2 - t_0)) dx_1 d_0 + dx_0^2 d_1) / (t_2 - t_0),
// and its mirror image last.

#include <Eigen/Core>

#include "cartan/numerics/cubic_hermite.hpp"

namespace cartan::numerics {

/// The not-a-knot spline through the columns of y (n x m, one column per node) at the m >= 2
/// strictly increasing, finite nodes t. Throws std::invalid_argument naming t or y otherwise.
CubicHermite not_a_knot_spline(const Eigen::VectorXd& t, const Eigen::MatrixXd& y);

}  // namespace cartan::numerics
