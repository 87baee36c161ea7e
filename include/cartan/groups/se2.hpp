#pragma once
// SE(2), the rigid motions of the plane, g = [[R(theta), t], [0, 1]] with t in R^2.
//
// Algebra coordinates, in this order: v = (x, y, theta), translation first, rotation last:
//   hat(v) = [[0, -theta, x], [theta, 0, y], [0, 0, 0]],
// i.e. E1, E2 = translations along x and y, E3 = the rotation generator; [E3, E1] = E2,
// [E3, E2] = -E1, [E1, E2] = 0.
// Class invariant: R is a rotation (to rounding) and the bottom row is exactly [0 0 1].
//
// Also defined here: SE2Generic (MatrixLieGroup, matrix_group.hpp), a reference for SE2.

#include <Eigen/Dense>
#include <array>
#include <string_view>

#include "cartan/groups/matrix_group.hpp"
#include "cartan/groups/so3.hpp"

namespace cartan::groups {

struct SE2 {
  static constexpr int kDim = 3;
  using Element = Eigen::Matrix3d;
  using Tangent = Eigen::Vector3d;  // (x, y, theta)
  using MatrixRep = Eigen::Matrix3d;
  using AlgebraMatrix = Eigen::Matrix3d;

  /// Default tolerance of `validate` (as SO3's for the rotation block; bottom row entrywise).
  static constexpr double kDefaultTolerance = SO3::kDefaultTolerance;

  static constexpr std::string_view name() { return "se2"; }
  static Element identity() { return Element::Identity(); }
  static Element compose(const Element& a, const Element& b) { return a * b; }
  /// [[R, t], [0, 1]]^{-1} = [[R^T, -R^T t], [0, 1]].
  static Element inverse(const Element& g);

  /// exp(x, y, theta) = [[R(theta), V(theta) (x, y)], [0, 1]] with
  /// V(theta) = (sin theta / theta) I + ((1 - cos theta)/theta) J, J = [[0, -1], [1, 0]]
  /// (coefficients from SO3::angle_coefficients, series for small theta).
  static Element exp(const Tangent& v);
  /// theta = atan2(R_10, R_00) in (-pi, pi], (x, y) = V(theta)^{-1} t with
  /// V^{-1} = (theta/2) cot(theta/2) I - (theta/2) J.
  static Tangent log(const Element& g);

  static MatrixRep hat(const Tangent& v);
  /// Reads theta from the skew-symmetric part of the rotation block, (x, y) from the last column.
  static Tangent vee(const MatrixRep& x);
  static MatrixRep matrix(const Element& g) { return g; }

  /// Ad(g) = [[R, (t_y, -t_x)^T], [0, 0, 1]].
  static AlgebraMatrix Ad(const Element& g);
  /// ad(x, y, theta) = [[0, -theta, y], [theta, 0, -x], [0, 0, 0]].
  static AlgebraMatrix ad(const Tangent& v);
  /// Left Jacobian of exp, sum_k ad_v^k / (k+1)!, in closed form. With ad_v = [[A, c], [0, 0]]
  /// (A = theta J, A^2 = -theta^2 I) it is [[phi1(A), phi2(A) c], [0, 1]], where
  /// phi1(A) = (sin t / t) I + ((1 - cos t)/t^2) A and phi2(A) = ((1 - cos t)/t^2) I + ((t - sin t)/t^3) A
  /// (the series of e^z with z^2 = -t^2; coefficients from SO3::angle_coefficients).
  static AlgebraMatrix left_jacobian(const Tangent& v);

  static Element left_translate(const Element& g, const Tangent& v) { return g * hat(v); }
  static Element right_translate(const Element& g, const Tangent& v) { return hat(v) * g; }
  static Tangent left_trivialise(const Element& g, const Element& x) { return vee(inverse(g) * x); }
  static Tangent right_trivialise(const Element& g, const Element& x) { return vee(x * inverse(g)); }

  /// Throws std::invalid_argument naming `name` and the matrix unless g is finite, its rotation
  /// block is orthogonal with determinant 1 (checked by SO3::validate on diag(R, 1)) and its
  /// bottom row is [0 0 1], within the tolerance.
  static void validate(const Element& g, std::string_view name);
  static void validate(const Element& g, std::string_view name, double tolerance);
};

/// se(2) basis in SE2's coordinate order: E_i = SE2::hat(e_i) written out.
struct SE2Basis {
  static constexpr int kDim = 3;
  static constexpr int kMatrixSize = 3;
  static constexpr std::string_view name() { return "se2-generic"; }
  static std::array<Eigen::Matrix3d, 3> basis() {
    std::array<Eigen::Matrix3d, 3> e;
    e[0] << 0, 0, 1, 0, 0, 0, 0, 0, 0;
    e[1] << 0, 0, 0, 0, 0, 1, 0, 0, 0;
    e[2] << 0, -1, 0, 1, 0, 0, 0, 0, 0;
    return e;
  }
};

using SE2Generic = MatrixLieGroup<SE2Basis>;

}  // namespace cartan::groups
