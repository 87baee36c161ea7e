// Spectra of small matrices (numerics/spectrum.hpp) against matrices built from their spectrum,
// on both paths: fixed-size for orders 2, 3 and 6, dynamic-size for the others; the pseudo-inverse
// against its closed form from a chosen SVD.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "cartan/numerics/spectrum.hpp"

namespace cartan::numerics {
namespace {

/// A random orthogonal n x n matrix (Householder QR of a random one; std::srand seeds it).
Eigen::MatrixXd random_orthogonal(Eigen::Index n) {
  return Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
}

/// Q diag(lambda) Q^T with a random orthogonal Q.
Eigen::MatrixXd with_spectrum(const Eigen::VectorXd& lambda, unsigned seed) {
  std::srand(seed);
  const Eigen::MatrixXd q = random_orthogonal(lambda.size());
  return q * lambda.asDiagonal() * q.transpose();
}

// Orthogonal similarity keeps the eigenvalues; a symmetric eigensolver recovers them to a few ulps
// of the largest (1e-13 relative: rounding of the similarity and of the QR iteration, n <= 8).
TEST(Spectrum, SymmetricEigenvaluesOfEveryOrderAreTheSpectrumAscending) {
  for (int n = 1; n <= 8; ++n) {
    Eigen::VectorXd lambda(n);
    for (int i = 0; i < n; ++i) lambda(i) = std::pow(-1.7, i) + 0.1 * i;  // distinct, both signs
    const Eigen::MatrixXd a = with_spectrum(lambda, 7u + static_cast<unsigned>(n));
    std::vector<double> sorted(lambda.data(), lambda.data() + n);
    std::sort(sorted.begin(), sorted.end());
    const Eigen::VectorXd found = symmetric_eigenvalues(a);
    ASSERT_EQ(found.size(), n);
    const double scale = lambda.cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i) EXPECT_NEAR(found(i), sorted[i], 1e-13 * scale) << "n = " << n << ", i = " << i;
    EXPECT_NEAR(smallest_symmetric_eigenvalue(a), sorted.front(), 1e-13 * scale) << "n = " << n;
  }
}

// Only the lower triangle is read (Eigen's self-adjoint solver): the upper one may hold anything.
TEST(Spectrum, OnlyTheLowerTriangleIsRead) {
  const Eigen::MatrixXd a = with_spectrum(Eigen::Vector3d(1, 2, 5), 3);
  Eigen::MatrixXd b = a;
  b(0, 1) = 100;
  b(0, 2) = -7;
  EXPECT_EQ(symmetric_eigenvalues(a), symmetric_eigenvalues(b));
  EXPECT_EQ(smallest_symmetric_eigenvalue(a), smallest_symmetric_eigenvalue(b));
}

TEST(Spectrum, EmptyMatrices) {
  EXPECT_EQ(symmetric_eigenvalues(Eigen::MatrixXd(0, 0)).size(), 0);
  EXPECT_TRUE(std::isnan(smallest_symmetric_eigenvalue(Eigen::MatrixXd(0, 0))));
}

// sigma_min / sigma_max, exactly for a rotated diagonal (orthogonal factors change no singular
// value; 1e-15: rounding of a 3 x 3 SVD) and for a 3 x 2 frame with orthogonal columns of lengths
// 2 and 0.5; 0 for a singular matrix, NaN for empty or non-finite input.
TEST(SingularValueRatio, ClosedFormsAndDegenerateInput) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::MatrixXd a = rotation * Eigen::Vector3d(4, 1, 2).asDiagonal() * rotation.transpose();
  EXPECT_NEAR(singular_value_ratio(a), 0.25, 1e-15);
  Eigen::Matrix<double, 3, 2> frame = rotation.leftCols<2>();
  frame.col(0) *= 2;
  frame.col(1) *= 0.5;
  EXPECT_NEAR(singular_value_ratio(frame), 0.25, 1e-15);
  EXPECT_EQ(singular_value_ratio(Eigen::MatrixXd::Zero(2, 2)), 0.0);
  EXPECT_TRUE(std::isnan(singular_value_ratio(Eigen::MatrixXd(0, 0))));
  Eigen::MatrixXd bad = a;
  bad(1, 1) = std::nan("");
  EXPECT_TRUE(std::isnan(singular_value_ratio(bad)));
}

// The pseudo-inverse of A = U_r diag(sigma) V_r^T (random orthogonal U, V; 6 x 8, rank 3, as it is
// and transposed) against its closed form V_r diag(1 / sigma) U_r^T and the Penrose conditions:
// A A+ A = A, A+ A A+ = A+, A A+ and A+ A symmetric. Tolerances: |A| = 2, |A+| = 2, so rounding of
// A (a few eps |A|), of the SVD (backward stable) and of the products here (sums of at most 8
// terms) moves each entry by some 1e-15; 1e-13 leaves room. The zero singular values of A come
// out at about eps |A|, below the rank threshold 6 eps |A|.
TEST(PseudoInverse, OfAMatrixOfKnownRankAgainstItsClosedForm) {
  const Eigen::Vector3d sigma(2, 1, 0.5);
  std::srand(11);
  const Eigen::MatrixXd u = random_orthogonal(6).leftCols(3), v = random_orthogonal(8).leftCols(3);
  const Eigen::MatrixXd a = u * sigma.asDiagonal() * v.transpose();
  const Eigen::MatrixXd expected = v * sigma.cwiseInverse().asDiagonal() * u.transpose();
  for (const bool transposed : {false, true}) {
    const Eigen::MatrixXd m = transposed ? Eigen::MatrixXd(a.transpose()) : a;
    const PseudoInverse p = pseudo_inverse(m);
    const Eigen::MatrixXd& plus = p.matrix;
    ASSERT_EQ(plus.rows(), m.cols()) << "transposed = " << transposed;
    ASSERT_EQ(plus.cols(), m.rows()) << "transposed = " << transposed;
    EXPECT_EQ(p.rank, 3) << "transposed = " << transposed;
    EXPECT_NEAR(p.smallest_singular_value, 0.5, 1e-14) << "transposed = " << transposed;
    EXPECT_LE((plus - (transposed ? Eigen::MatrixXd(expected.transpose()) : expected)).cwiseAbs().maxCoeff(), 1e-13);
    EXPECT_LE((m * plus * m - m).cwiseAbs().maxCoeff(), 1e-13) << "transposed = " << transposed;
    EXPECT_LE((plus * m * plus - plus).cwiseAbs().maxCoeff(), 1e-13) << "transposed = " << transposed;
    const Eigen::MatrixXd left = m * plus, right = plus * m;
    EXPECT_LE((left - left.transpose()).cwiseAbs().maxCoeff(), 1e-13) << "transposed = " << transposed;
    EXPECT_LE((right - right.transpose()).cwiseAbs().maxCoeff(), 1e-13) << "transposed = " << transposed;
  }
}

// Full rank: the inverse, here of R diag(4, 1, 2) R^T, R diag(1/4, 1, 1/2) R^T (1e-14: entries at
// most 1, condition 4). Rank 0: zero, with an infinite smallest kept singular value; empty: empty.
TEST(PseudoInverse, FullRankZeroAndEmptyMatrices) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const PseudoInverse full = pseudo_inverse(rotation * Eigen::Vector3d(4, 1, 2).asDiagonal() * rotation.transpose());
  EXPECT_LE((full.matrix - rotation * Eigen::Vector3d(0.25, 1, 0.5).asDiagonal() * rotation.transpose()).cwiseAbs().maxCoeff(),
            1e-14);
  EXPECT_EQ(full.rank, 3);
  EXPECT_NEAR(full.smallest_singular_value, 1, 1e-14);
  const PseudoInverse zero = pseudo_inverse(Eigen::MatrixXd::Zero(2, 3));
  EXPECT_EQ(zero.matrix, Eigen::MatrixXd::Zero(3, 2));
  EXPECT_EQ(zero.rank, 0);
  EXPECT_TRUE(std::isinf(zero.smallest_singular_value));
  const PseudoInverse empty = pseudo_inverse(Eigen::MatrixXd(0, 3));
  EXPECT_EQ(empty.matrix.rows(), 3);
  EXPECT_EQ(empty.matrix.cols(), 0);
  EXPECT_EQ(empty.rank, 0);
  Eigen::MatrixXd bad = Eigen::MatrixXd::Identity(2, 2);
  bad(0, 1) = std::nan("");
  EXPECT_THROW(pseudo_inverse(bad), std::invalid_argument);
}

}  // namespace
}  // namespace cartan::numerics
