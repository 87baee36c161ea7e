#pragma once
// SE(3), the rigid motions of space, g = [[R, t], [0, 1]] with R in SO(3), t in R^3.
//
// Algebra coordinates, in this order: v = (rho, omega) in R^6, rho = translation part first,
// omega = rotation part second:
//   hat(v) = [[hat(omega), rho], [0, 0]]   (hat(omega) = SO3::hat, hat(omega) w = omega x w),
// i.e. the basis E1..E3 = translations along x, y, z and E4..E6 = SO(3)'s E1..E3 embedded.
// Brackets: [(rho, omega), (rho', omega')] = (omega x rho' - omega' x rho, omega x omega').
// Class invariant: R is a rotation (to rounding) and the bottom row is exactly [0 0 0 1].
//
// Also defined here: the generic matrix-group versions SO3Generic and SE3Generic
// (MatrixLieGroup, matrix_group.hpp), references for SO3 and SE3.

#include <Eigen/Dense>
#include <array>
#include <string_view>

#include "cartan/groups/matrix_group.hpp"
#include "cartan/groups/so3.hpp"

namespace cartan::groups {

struct SE3 {
  static constexpr int kDim = 6;
  using Element = Eigen::Matrix4d;
  using Tangent = Eigen::Matrix<double, 6, 1>;  // (rho, omega)
  using MatrixRep = Eigen::Matrix4d;
  using AlgebraMatrix = Eigen::Matrix<double, 6, 6>;

  /// Default tolerance of `validate` (rotation block as in SO3, bottom row entrywise).
  static constexpr double kDefaultTolerance = SO3::kDefaultTolerance;

  static constexpr std::string_view name() { return "se3"; }
  static Element identity() { return Element::Identity(); }
  static Element compose(const Element& a, const Element& b) { return a * b; }
  /// [[R, t], [0, 1]]^{-1} = [[R^T, -R^T t], [0, 1]].
  static Element inverse(const Element& g);

  /// Builds [[R, t], [0, 1]] (no validation).
  static Element from_rotation_translation(const Eigen::Matrix3d& r, const Eigen::Vector3d& t);
  static Eigen::Matrix3d rotation(const Element& g) { return g.topLeftCorner<3, 3>(); }
  static Eigen::Vector3d translation(const Element& g) { return g.topRightCorner<3, 1>(); }
  static Eigen::Vector3d rho(const Tangent& v) { return v.head<3>(); }
  static Eigen::Vector3d omega(const Tangent& v) { return v.tail<3>(); }

  /// exp(rho, omega) = [[SO3::exp(omega), J(omega) rho], [0, 1]] with J the SO(3) left
  /// Jacobian (SO3::left_jacobian, series for small |omega|).
  static Element exp(const Tangent& v);
  /// omega = SO3::log(R) (|omega| <= pi, accurate near 0 and pi), rho = J(omega)^{-1} t.
  static Tangent log(const Element& g);

  static MatrixRep hat(const Tangent& v);
  /// Reads omega from the skew-symmetric part of the top-left block and rho from the last column.
  static Tangent vee(const MatrixRep& x);
  static MatrixRep matrix(const Element& g) { return g; }

  /// Ad(g) = [[R, hat(t) R], [0, R]].
  static AlgebraMatrix Ad(const Element& g);
  /// ad(rho, omega) = [[hat(omega), hat(rho)], [0, hat(omega)]].
  static AlgebraMatrix ad(const Tangent& v);
  /// Left Jacobian of exp, sum_k ad_v^k / (k+1)!, in closed form: [[J(omega), Q], [0, J(omega)]]
  /// with J the SO(3) left Jacobian and Q the derivative of J at hat(omega) along hat(rho),
  ///   Q = R/2 + c1 (W R + R W + W R W) + c2 (W^2 R + R W^2 - 3 W R W) + c3 (W R W^2 + W^2 R W),
  /// W = hat(omega), R = hat(rho), t = |omega|, c1 = (t - sin t)/t^3,
  /// c2 = (t^2 + 2 cos t - 2)/(2 t^4), c3 = (2 t - 3 sin t + t cos t)/(2 t^5) (series below t = 1e-2).
  static AlgebraMatrix left_jacobian(const Tangent& v);

  static Element left_translate(const Element& g, const Tangent& v) { return g * hat(v); }
  static Element right_translate(const Element& g, const Tangent& v) { return hat(v) * g; }
  static Tangent left_trivialise(const Element& g, const Element& x) { return vee(inverse(g) * x); }
  static Tangent right_trivialise(const Element& g, const Element& x) { return vee(x * inverse(g)); }

  /// Throws std::invalid_argument naming `name` and the matrix unless g is finite, its rotation
  /// block passes SO3::validate and its bottom row is [0 0 0 1], within the tolerance.
  static void validate(const Element& g, std::string_view name);
  static void validate(const Element& g, std::string_view name, double tolerance);
};

/// so(3) basis of the paper: E_i = SO3::hat(e_i), so hat(v) w = v x w and [E1, E2] = E3.
struct SO3Basis {
  static constexpr int kDim = 3;
  static constexpr int kMatrixSize = 3;
  static constexpr std::string_view name() { return "so3-generic"; }
  static std::array<Eigen::Matrix3d, 3> basis() {
    return {SO3::hat(Eigen::Vector3d::UnitX()), SO3::hat(Eigen::Vector3d::UnitY()),
            SO3::hat(Eigen::Vector3d::UnitZ())};
  }
};

/// se(3) basis in SE3's coordinate order (rho, omega): E1..E3 have a single 1 in the last
/// column (translation along x, y, z), E4..E6 are SO3Basis in the top-left block.
struct SE3Basis {
  static constexpr int kDim = 6;
  static constexpr int kMatrixSize = 4;
  static constexpr std::string_view name() { return "se3-generic"; }
  static std::array<Eigen::Matrix4d, 6> basis() {
    const std::array<Eigen::Matrix3d, 3> rotations = SO3Basis::basis();
    std::array<Eigen::Matrix4d, 6> e;
    for (int k = 0; k < 3; ++k) {
      e[k] = Eigen::Matrix4d::Zero();
      e[k](k, 3) = 1;
      e[k + 3] = Eigen::Matrix4d::Zero();
      e[k + 3].topLeftCorner<3, 3>() = rotations[k];
    }
    return e;
  }
};

using SO3Generic = MatrixLieGroup<SO3Basis>;
using SE3Generic = MatrixLieGroup<SE3Basis>;

}  // namespace cartan::groups
