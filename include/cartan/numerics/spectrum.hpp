#pragma once
// Spectra of small matrices, out of line: the eigen- and singular-value decompositions are
// compiled once, in the library, instead of in every unit that validates an inertia, a frame or a
// Lie algebra's basis, verifies a solution or converts a Lie-kernel result (each fixed-size
// decomposition costs a unit a few seconds of compile time; bench/README.md "Build time").
// Matrices of order 2, 3 and 6 (the shipped manifolds and groups) take a fixed-size path without
// allocation, others a dynamic-size one; pseudo_inverse is dynamic-size only (it runs once per
// group).

#include <Eigen/Core>
#include <limits>

namespace cartan::numerics {

/// The eigenvalues of the symmetric matrix `a`, ascending (only its lower triangle is read).
Eigen::VectorXd symmetric_eigenvalues(const Eigen::Ref<const Eigen::MatrixXd>& a);

/// The smallest eigenvalue of the symmetric matrix `a` (only its lower triangle is read); NaN for
/// an empty matrix.
double smallest_symmetric_eigenvalue(const Eigen::Ref<const Eigen::MatrixXd>& a);

/// sigma_min / sigma_max of `a` (0 when singular; NaN for an empty or non-finite matrix).
double singular_value_ratio(const Eigen::Ref<const Eigen::MatrixXd>& a);

/// The Moore–Penrose pseudo-inverse of a matrix, with the rank it was taken at.
struct PseudoInverse {
  Eigen::MatrixXd matrix;  ///< a^+, a.cols() x a.rows()
  Eigen::Index rank = 0;
  /// The smallest singular value kept (the smallest nonzero one); infinite at rank 0.
  double smallest_singular_value = std::numeric_limits<double>::infinity();
};

/// a^+ by a thin Jacobi SVD, the singular values below Eigen's default rank threshold
/// (min(rows, cols) eps sigma_max) dropped: the minimum-norm least-squares solution operator.
/// An empty `a` gives an empty a^+ at rank 0. Throws std::invalid_argument for a non-finite `a`.
PseudoInverse pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& a);

}  // namespace cartan::numerics
