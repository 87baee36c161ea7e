#pragma once
// Spectra of small matrices, out of line: the eigen- and singular-value decompositions are
// compiled once, in the library, instead of in every unit that validates an inertia, a frame or a
// Lie algebra's basis, or verifies a solution (each fixed-size decomposition costs a unit a few
// seconds of compile time; bench/README.md "Build time"). Matrices of order 2, 3 and 6 (the shipped
// manifolds and groups) take a fixed-size path without allocation, others a dynamic-size one.

#include <Eigen/Core>

namespace cartan::numerics {

/// The eigenvalues of the symmetric matrix `a`, ascending (only its lower triangle is read).
Eigen::VectorXd symmetric_eigenvalues(const Eigen::Ref<const Eigen::MatrixXd>& a);

/// The smallest eigenvalue of the symmetric matrix `a` (only its lower triangle is read); NaN for
/// an empty matrix.
double smallest_symmetric_eigenvalue(const Eigen::Ref<const Eigen::MatrixXd>& a);

/// sigma_min / sigma_max of `a` (0 when singular; NaN for an empty or non-finite matrix).
double singular_value_ratio(const Eigen::Ref<const Eigen::MatrixXd>& a);

}  // namespace cartan::numerics
