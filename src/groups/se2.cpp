#include "cartan/groups/se2.hpp"

#include <cmath>
#include <string>

#include "cartan/errors.hpp"
#include "cartan/groups/so3.hpp"

namespace cartan::groups {
namespace {

/// J (x, y) = (-y, x), rotation by +pi/2.
Eigen::Vector2d rotate_quarter_turn(const Eigen::Vector2d& p) { return Eigen::Vector2d(-p.y(), p.x()); }

SE2::Element from_rotation_translation(const Eigen::Matrix2d& r, const Eigen::Vector2d& t) {
  SE2::Element g = SE2::Element::Identity();
  g.topLeftCorner<2, 2>() = r;
  g.topRightCorner<2, 1>() = t;
  return g;
}

}  // namespace

SE2::Element SE2::inverse(const Element& g) {
  const Eigen::Matrix2d r_inv = g.topLeftCorner<2, 2>().transpose();
  return from_rotation_translation(r_inv, -r_inv * g.topRightCorner<2, 1>());
}

SE2::Element SE2::exp(const Tangent& v) {
  const double theta = v[2];
  const Eigen::Vector2d rho = v.head<2>();
  const SO3::AngleCoefficients k = SO3::angle_coefficients(theta);
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d r;
  r << c, -s, s, c;
  return from_rotation_translation(r, k.sin_over_t * rho + theta * k.one_minus_cos_over_t2 * rotate_quarter_turn(rho));
}

SE2::Tangent SE2::log(const Element& g) {
  const double theta = std::atan2(g(1, 0), g(0, 0));
  const Eigen::Vector2d t = g.topRightCorner<2, 1>();
  const SO3::AngleCoefficients k = SO3::angle_coefficients(theta);
  // (theta/2) cot(theta/2) = 1 - theta^2 (1 - (theta/2) cot(theta/2)) / theta^2
  const double half_cot = 1 - theta * theta * k.one_minus_half_cot_over_t2;
  Tangent v;
  v << half_cot * t - theta / 2 * rotate_quarter_turn(t), theta;
  return v;
}

SE2::MatrixRep SE2::hat(const Tangent& v) {
  MatrixRep x;
  x << 0, -v[2], v[0],  //
      v[2], 0, v[1],    //
      0, 0, 0;
  return x;
}

SE2::Tangent SE2::vee(const MatrixRep& x) { return Tangent(x(0, 2), x(1, 2), (x(1, 0) - x(0, 1)) / 2); }

SE2::AlgebraMatrix SE2::Ad(const Element& g) {
  AlgebraMatrix m = AlgebraMatrix::Identity();
  m.topLeftCorner<2, 2>() = g.topLeftCorner<2, 2>();
  m(0, 2) = g(1, 2);
  m(1, 2) = -g(0, 2);
  return m;
}

SE2::AlgebraMatrix SE2::ad(const Tangent& v) {
  AlgebraMatrix m;
  m << 0, -v[2], v[1],  //
      v[2], 0, -v[0],   //
      0, 0, 0;
  return m;
}

SE2::AlgebraMatrix SE2::left_jacobian(const Tangent& v) {
  const AlgebraMatrix x = ad(v);
  const Eigen::Matrix2d a = x.topLeftCorner<2, 2>();
  const SO3::AngleCoefficients k = SO3::angle_coefficients(v[2]);
  AlgebraMatrix j = AlgebraMatrix::Zero();
  j.topLeftCorner<2, 2>() = k.sin_over_t * Eigen::Matrix2d::Identity() + k.one_minus_cos_over_t2 * a;
  j.topRightCorner<2, 1>() =
      (k.one_minus_cos_over_t2 * Eigen::Matrix2d::Identity() + k.t_minus_sin_over_t3 * a) * x.topRightCorner<2, 1>();
  j(2, 2) = 1;
  return j;
}

void SE2::validate(const Element& g, std::string_view name) { validate(g, name, kDefaultTolerance); }

void SE2::validate(const Element& g, std::string_view name, double tolerance) {
  require_finite(g, "SE2", name);
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  rotation.topLeftCorner<2, 2>() = g.topLeftCorner<2, 2>();
  try {
    SO3::validate(rotation, std::string(name) + " rotation block diag(R, 1)", tolerance);
  } catch (const std::invalid_argument& e) {
    throw_invalid("SE2", name, format_value(g), std::string("has an invalid rotation block (") + e.what() + ")");
  }
  const double bottom_row_error = (g.row(2) - Eigen::RowVector3d(0, 0, 1)).cwiseAbs().maxCoeff();
  if (bottom_row_error > tolerance) {
    throw_invalid("SE2", name, format_value(g),
                  "has bottom row " + format_value(g.row(2)) + ", not [0, 0, 1] (max deviation " +
                      format_value(bottom_row_error) + " > tolerance " + format_value(tolerance) + ")");
  }
}

}  // namespace cartan::groups
