#include "cartan/numerics/spectrum.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <limits>

#include "cartan/errors.hpp"

namespace cartan::numerics {
namespace {

/// The eigenvalues of `a`, ascending, by Eigen's self-adjoint solver at the fixed size n (without
/// allocation): the orders of the shipped manifolds and groups (2, 3 and 6); other orders take the
/// dynamic-size path.
template <int n>
Eigen::Matrix<double, n, 1> eigenvalues_of_order(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  using Matrix = Eigen::Matrix<double, n, n>;
  return Eigen::SelfAdjointEigenSolver<Matrix>(Matrix(a), Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace

Eigen::VectorXd symmetric_eigenvalues(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  switch (a.rows()) {
    case 0: return Eigen::VectorXd();
    case 2: return eigenvalues_of_order<2>(a);
    case 3: return eigenvalues_of_order<3>(a);
    case 6: return eigenvalues_of_order<6>(a);
    default: return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly).eigenvalues();
  }
}

double smallest_symmetric_eigenvalue(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  switch (a.rows()) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 2: return eigenvalues_of_order<2>(a)[0];
    case 3: return eigenvalues_of_order<3>(a)[0];
    case 6: return eigenvalues_of_order<6>(a)[0];
    default: return symmetric_eigenvalues(a)[0];
  }
}

double singular_value_ratio(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  if (a.size() == 0 || !a.allFinite()) return std::numeric_limits<double>::quiet_NaN();
  // One-sided Jacobi: singular values to high relative accuracy; compiles in a third of the time
  // of BDCSVD (bench/README.md "Build time"), and the matrices here are small.
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(a).singularValues();
  return sigma(0) > 0 ? sigma(sigma.size() - 1) / sigma(0) : 0.0;
}

PseudoInverse pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  require_finite(a, "pseudo_inverse", "a");
  PseudoInverse out;
  if (a.size() == 0) {
    out.matrix.resize(a.cols(), a.rows());
    return out;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  // solve drops the singular values below the rank threshold: on the identity it gives a^+.
  out.matrix = svd.solve(Eigen::MatrixXd::Identity(a.rows(), a.rows()));
  out.rank = svd.rank();
  if (out.rank > 0) out.smallest_singular_value = svd.singularValues()[out.rank - 1];
  return out;
}

}  // namespace cartan::numerics
