// Spectra of small matrices (numerics/spectrum.hpp) against matrices built from their spectrum,
// on both paths: fixed-size for orders 2, 3 and 6, dynamic-size for the others.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "cartan/numerics/spectrum.hpp"

namespace cartan::numerics {
namespace {

/// Q diag(lambda) Q^T with a random orthogonal Q (Householder QR of a random matrix).
Eigen::MatrixXd with_spectrum(const Eigen::VectorXd& lambda, unsigned seed) {
  std::srand(seed);
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(lambda.size(), lambda.size())).householderQ();
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

}  // namespace
}  // namespace cartan::numerics
