#include "cartan/groups/so3.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <numbers>

#include "cartan/errors.hpp"

namespace cartan::groups {

SO3::AngleCoefficients SO3::angle_coefficients(double t) {
  const double t2 = t * t;
  if (std::abs(t) < kSmallAngle) {  // first omitted terms are O(t^6) relative
    return {1 - t2 / 6 * (1 - t2 / 20), 0.5 - t2 / 24 * (1 - t2 / 30), (1 - t2 / 20 * (1 - t2 / 42)) / 6,
            (1 + t2 / 60 * (1 + t2 / 42)) / 12};
  }
  // (1 - cos t)/t^2 = (sin(t/2)/(t/2))^2 / 2 without the cancellation in 1 - cos t (relative
  // error eps/t^2), which the left Jacobian would multiply by |hat(v)| = t, not t^2. The two
  // other differences lose digits the same way but multiply hat(v)^2, so their absolute error
  // there stays O(eps).
  const double half = t / 2;
  const double sin_half_over_half = std::sin(half) / half;
  return {std::sin(t) / t, sin_half_over_half * sin_half_over_half / 2, (t - std::sin(t)) / (t2 * t),
          (1 - half / std::tan(half)) / t2};
}

Eigen::Matrix3d SO3::left_jacobian_inverse(const Tangent& v) {
  const AngleCoefficients k = angle_coefficients(v.norm());
  const MatrixRep w = hat(v);
  return Eigen::Matrix3d::Identity() - w / 2 + k.one_minus_half_cot_over_t2 * w * w;
}

SO3::Tangent SO3::log(const Element& r) {
  const Tangent s = vee(r);          // sin(t) n
  const double c = (r.trace() - 1) / 2;  // cos(t)
  const double sn = s.norm();
  const double t = std::atan2(sn, c);
  if (t < kSmallAngle) return s * (1 + t * t / 6 * (1 + 7 * t * t / 60));  // t / sin t series
  if (c > -0.5) return s * (t / sn);
  // Near pi the skew part is small; R + R^T = 2cI + 2(1-c) n n^T gives the axis accurately.
  Eigen::Matrix3d nn = ((r + r.transpose()) / 2 - c * Eigen::Matrix3d::Identity()) / (1 - c);
  Eigen::Index k;
  nn.diagonal().maxCoeff(&k);
  Tangent n = nn.col(k) / std::sqrt(nn(k, k));
  n.normalize();
  if (n.dot(s) < 0) n = -n;
  return t * n;
}

void SO3::validate(const Element& r, std::string_view name) { validate(r, name, kDefaultTolerance); }

void SO3::validate(const Element& r, std::string_view name, double tolerance) {
  require_finite(r, "SO3", name);
  const double orth = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orth > tolerance) {
    throw_invalid("SO3", name, format_value(r),
                  "is not orthogonal: max|R^T R - I| = " + format_value(orth) + " > tolerance " +
                      format_value(tolerance));
  }
  const double det = r.determinant();
  if (std::abs(det - 1) > tolerance) {
    throw_invalid("SO3", name, format_value(r),
                  "has determinant " + format_value(det) + ", not 1 (a reflection?)");
  }
}

SO3::Element SO3::from_matrix(const Eigen::Matrix3d& m, double tolerance) {
  require_finite(tolerance, "SO3::from_matrix", "tolerance");
  if (!(tolerance > 0)) throw_invalid("SO3::from_matrix", "tolerance", format_value(tolerance), "must be positive");
  validate(m, "matrix", tolerance);
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();  // det > 0 since m is near SO(3)
}

SO3::Element SO3::minimal_rotation(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  require_finite(a, "SO3::minimal_rotation", "a");
  require_finite(b, "SO3::minimal_rotation", "b");
  // stable: the plain norm of |a| ~ 1e200 overflows (x = 0, the identity returned) and of
  // |a| ~ 1e-200 underflows (a valid direction reported as zero)
  if (a.stableNorm() == 0) throw_invalid("SO3::minimal_rotation", "a", format_value(a), "has zero length");
  if (b.stableNorm() == 0) throw_invalid("SO3::minimal_rotation", "b", format_value(b), "has zero length");
  const Eigen::Vector3d x = a.stableNormalized();
  const Eigen::Vector3d y = b.stableNormalized();
  const Eigen::Vector3d axis = x.cross(y);
  const double s = axis.norm();
  const double c = x.dot(y);
  if (s < 1e-12 && c < 0) {
    throw_invalid("SO3::minimal_rotation", "(a, b)", format_value(a) + ", " + format_value(b),
                  "are antiparallel: the minimal rotation is not unique (give the target rotation instead)");
  }
  if (s == 0) return Element::Identity();
  return exp(axis / s * std::atan2(s, c));
}

}  // namespace cartan::groups
