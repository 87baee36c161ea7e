#include "cartan/groups/se3.hpp"

#include <string>

#include "cartan/errors.hpp"

namespace cartan::groups {

SE3::Element SE3::from_rotation_translation(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
  Element g = Element::Identity();
  g.topLeftCorner<3, 3>() = r;
  g.topRightCorner<3, 1>() = t;
  return g;
}

SE3::Element SE3::inverse(const Element& g) {
  const Eigen::Matrix3d r_inv = rotation(g).transpose();
  return from_rotation_translation(r_inv, -r_inv * translation(g));
}

SE3::Element SE3::exp(const Tangent& v) {
  return from_rotation_translation(SO3::exp(omega(v)), SO3::left_jacobian(omega(v)) * rho(v));
}

SE3::Tangent SE3::log(const Element& g) {
  const Eigen::Vector3d w = SO3::log(rotation(g));
  Tangent v;
  v << SO3::left_jacobian_inverse(w) * translation(g), w;
  return v;
}

SE3::MatrixRep SE3::hat(const Tangent& v) {
  MatrixRep x = MatrixRep::Zero();
  x.topLeftCorner<3, 3>() = SO3::hat(omega(v));
  x.topRightCorner<3, 1>() = rho(v);
  return x;
}

SE3::Tangent SE3::vee(const MatrixRep& x) {
  Tangent v;
  v << x.topRightCorner<3, 1>(), SO3::vee(x.topLeftCorner<3, 3>());
  return v;
}

SE3::AlgebraMatrix SE3::Ad(const Element& g) {
  const Eigen::Matrix3d r = rotation(g);
  AlgebraMatrix m = AlgebraMatrix::Zero();
  m.topLeftCorner<3, 3>() = r;
  m.topRightCorner<3, 3>() = SO3::hat(translation(g)) * r;
  m.bottomRightCorner<3, 3>() = r;
  return m;
}

SE3::AlgebraMatrix SE3::left_jacobian(const Tangent& v) {
  const Eigen::Matrix3d w = SO3::hat(omega(v)), r = SO3::hat(rho(v));
  const double t = omega(v).norm(), t2 = t * t;
  double c1, c2, c3;
  if (t < 1e-2) {  // next terms: t^4/5040, t^4/40320, t^4/~2e5 relative; they multiply W^2.. of size t^2
    c1 = 1.0 / 6 - t2 / 120;
    c2 = 1.0 / 24 - t2 / 720;
    c3 = 1.0 / 120 - t2 / 2520;
  } else {
    const double s = std::sin(t), c = std::cos(t);
    c1 = (t - s) / (t2 * t);
    c2 = (t2 + 2 * c - 2) / (2 * t2 * t2);
    c3 = (2 * t - 3 * s + t * c) / (2 * t2 * t2 * t);
  }
  const Eigen::Matrix3d wr = w * r, rw = r * w, wrw = wr * w, ww = w * w;
  const Eigen::Matrix3d q = r / 2 + c1 * (wr + rw + wrw) + c2 * (ww * r + rw * w - 3 * wrw) + c3 * (wrw * w + w * wrw);
  const Eigen::Matrix3d j = SO3::left_jacobian(omega(v));
  AlgebraMatrix out = AlgebraMatrix::Zero();
  out.topLeftCorner<3, 3>() = j;
  out.topRightCorner<3, 3>() = q;
  out.bottomRightCorner<3, 3>() = j;
  return out;
}

SE3::AlgebraMatrix SE3::ad(const Tangent& v) {
  const Eigen::Matrix3d w = SO3::hat(omega(v));
  AlgebraMatrix m = AlgebraMatrix::Zero();
  m.topLeftCorner<3, 3>() = w;
  m.topRightCorner<3, 3>() = SO3::hat(rho(v));
  m.bottomRightCorner<3, 3>() = w;
  return m;
}

void SE3::validate(const Element& g, std::string_view name) { validate(g, name, kDefaultTolerance); }

void SE3::validate(const Element& g, std::string_view name, double tolerance) {
  require_finite(g, "SE3", name);
  try {
    SO3::validate(rotation(g), std::string(name) + " rotation block", tolerance);
  } catch (const std::invalid_argument& e) {
    throw_invalid("SE3", name, format_value(g), std::string("has an invalid rotation block (") + e.what() + ")");
  }
  const double bottom_row_error = (g.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff();
  if (bottom_row_error > tolerance) {
    throw_invalid("SE3", name, format_value(g),
                  "has bottom row " + format_value(g.row(3)) + ", not [0, 0, 0, 1] (max deviation " +
                      format_value(bottom_row_error) + " > tolerance " + format_value(tolerance) + ")");
  }
}

}  // namespace cartan::groups
