#pragma once
// Jacobians of the exponential map, generic over the group (closed forms when the group has
// them, e.g. SO3::left_jacobian). Conventions:
//   left Jacobian   J_l(x) = sum_k ad_x^k / (k+1)!     exp(x + s w) = exp(s J_l(x) w) exp(x) + O(s^2)
//   right Jacobian  J_r(x) = J_l(-x)                   exp(x + s w) = exp(x) exp(s J_r(x) w) + O(s^2)
// so that log(g exp(s w)) = log(g) + s J_r(log g)^{-1} w + O(s^2).

#include <unsupported/Eigen/MatrixFunctions>
#include <utility>

#include "cartan/groups/group.hpp"

namespace cartan::groups {

namespace detail {
/// phi_1(A) = sum_k A^k / (k+1)! from the exponential of the block matrix [[A, I], [0, 0]].
template <int N>
Eigen::Matrix<double, N, N> phi1(const Eigen::Matrix<double, N, N>& a) {
  Eigen::Matrix<double, 2 * N, 2 * N> block = Eigen::Matrix<double, 2 * N, 2 * N>::Zero();
  block.template topLeftCorner<N, N>() = a;
  block.template topRightCorner<N, N>().setIdentity();
  const Eigen::Matrix<double, 2 * N, 2 * N> e = block.exp();
  return e.template topRightCorner<N, N>();
}
}  // namespace detail

template <LieGroup G>
AlgebraMatrixOf<G> left_jacobian(const TangentOf<G>& x) {
  if constexpr (requires { G::left_jacobian(x); }) {
    return G::left_jacobian(x);
  } else {
    return detail::phi1<G::kDim>(G::ad(x));
  }
}

template <LieGroup G>
AlgebraMatrixOf<G> right_jacobian(const TangentOf<G>& x) {
  return left_jacobian<G>(TangentOf<G>(-x));
}

/// exp(x) and J_l(x) together: the group's fused `exp_and_left_jacobian` when it has one (they
/// share the trigonometric work on SO(3)), else the two computed apart.
template <LieGroup G>
std::pair<ElementOf<G>, AlgebraMatrixOf<G>> exp_and_left_jacobian(const TangentOf<G>& x) {
  if constexpr (requires { G::exp_and_left_jacobian(x); }) {
    return G::exp_and_left_jacobian(x);
  } else {
    return {G::exp(x), left_jacobian<G>(x)};
  }
}

template <LieGroup G>
AlgebraMatrixOf<G> left_jacobian_inverse(const TangentOf<G>& x) {
  if constexpr (requires { G::left_jacobian_inverse(x); }) {
    return G::left_jacobian_inverse(x);
  } else {
    return left_jacobian<G>(x).inverse();
  }
}

template <LieGroup G>
AlgebraMatrixOf<G> right_jacobian_inverse(const TangentOf<G>& x) {
  return left_jacobian_inverse<G>(TangentOf<G>(-x));
}

}  // namespace cartan::groups
