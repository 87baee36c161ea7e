#pragma once
// SO(3), the rotation group (paper: Section "Application to the rigid body" and the appendix
// "The Lie algebra so(3) and its dual").
//
// Basis of so(3) (paper): E1, E2, E3 with hat(v) w = v x w and [E1,E2] = E3 (cyclic).
// Dual: mu in R^3 pairs as mu . v (the paper's breve map), so ad*_v mu = -v x mu.
// Class invariant: an Element R satisfies R^T R = I and det R = 1 (to rounding).

#include <Eigen/Dense>
#include <cmath>
#include <string_view>
#include <utility>

namespace cartan::groups {

struct SO3 {
  static constexpr int kDim = 3;
  using Element = Eigen::Matrix3d;
  using Tangent = Eigen::Vector3d;
  using MatrixRep = Eigen::Matrix3d;
  using AlgebraMatrix = Eigen::Matrix3d;

  /// Rotation angles below this use Taylor series in exp/log (relative error < 1e-16 there).
  static constexpr double kSmallAngle = 1e-4;
  /// Default tolerance of `validate` for |R^T R - I| (max norm) and |det R - 1|.
  static constexpr double kDefaultTolerance = 1e-9;

  static constexpr std::string_view name() { return "so3"; }
  static Element identity() { return Element::Identity(); }
  static Element compose(const Element& a, const Element& b) { return a * b; }
  static Element inverse(const Element& r) { return r.transpose(); }

  /// The scalar functions of the angle t = |v| in the closed forms of SO(3) and of the rigid
  /// motion groups built on it (SE(2), SE(3)); Taylor series when t < kSmallAngle.
  struct AngleCoefficients {
    double sin_over_t;                 // sin t / t
    double one_minus_cos_over_t2;      // (1 - cos t) / t^2
    double t_minus_sin_over_t3;        // (t - sin t) / t^3
    double one_minus_half_cot_over_t2; // (1 - (t/2) cot(t/2)) / t^2, finite for |t| < 2 pi
  };
  static AngleCoefficients angle_coefficients(double t);

  /// sin t / t and (1 - cos t)/t^2, the two coefficients of Rodrigues' formula, from one sine and
  /// cosine of t/2: sin t / t = (sin(t/2)/(t/2)) cos(t/2) and (1 - cos t)/t^2 = (sin(t/2)/(t/2))^2 / 2,
  /// the latter without the cancellation of 1 - cos t. Taylor series when t < kSmallAngle.
  struct ExpCoefficients {
    double sin_over_t;
    double one_minus_cos_over_t2;
  };
  static ExpCoefficients exp_coefficients(double t) {
    if (std::abs(t) < kSmallAngle) {
      const double t2 = t * t;
      return {1 - t2 / 6 * (1 - t2 / 20), 0.5 - t2 / 24 * (1 - t2 / 30)};
    }
    const double half = t / 2;
    const double sinc_half = std::sin(half) / half;
    return {sinc_half * std::cos(half), sinc_half * sinc_half / 2};
  }

  /// Rodrigues' formula exp(hat(v)) = I + (sin t / t) hat(v) + ((1 - cos t)/t^2) hat(v)^2.
  static Element exp(const Tangent& v) {
    const ExpCoefficients k = exp_coefficients(v.norm());
    const MatrixRep w = hat(v);
    const MatrixRep w2 = w * w;  // evaluated as in exp_and_left_jacobian, so that both agree to the bit
    return Element::Identity() + k.sin_over_t * w + k.one_minus_cos_over_t2 * w2;
  }
  /// Left Jacobian of exp, J(v) = sum_k ad_v^k / (k+1)!
  ///   = I + ((1 - cos t)/t^2) hat(v) + ((t - sin t)/t^3) hat(v)^2,
  /// so that d/ds exp(v + s w) at s = 0 equals hat(J(v) w) exp(v).
  static Eigen::Matrix3d left_jacobian(const Tangent& v) { return exp_and_left_jacobian(v).second; }
  /// exp(v) and J(v) together: one sine and cosine for both (the tangent-linear scheme needs both
  /// at every step). exp(v) is the same, to the last bit, as `exp`; and exp(-v) = exp(v)^T exactly.
  static std::pair<Element, Eigen::Matrix3d> exp_and_left_jacobian(const Tangent& v) {
    const double t = v.norm();
    const ExpCoefficients k = exp_coefficients(t);
    // (t - sin t)/t^3 = (1 - sin t / t)/t^2: series below 1e-2, where the difference would lose
    // more than 4 digits (it multiplies hat(v)^2, of size t^2: the absolute error stays O(eps)).
    const double t2 = t * t;
    const double c3 = t < 1e-2 ? (1 - t2 / 20 * (1 - t2 / 42 * (1 - t2 / 72))) / 6 : (1 - k.sin_over_t) / t2;
    const MatrixRep w = hat(v);
    const MatrixRep w2 = w * w;
    return {Element::Identity() + k.sin_over_t * w + k.one_minus_cos_over_t2 * w2,
            Eigen::Matrix3d::Identity() + k.one_minus_cos_over_t2 * w + c3 * w2};
  }
  /// J(v)^{-1} = I - hat(v)/2 + ((1 - (t/2) cot(t/2))/t^2) hat(v)^2, for t = |v| < 2 pi.
  static Eigen::Matrix3d left_jacobian_inverse(const Tangent& v);
  /// Principal logarithm, |log R| in [0, pi]. Stable near 0 (series) and near pi (axis from
  /// the symmetric part of R). At exactly pi either of the two logarithms may be returned.
  /// R is not checked: the formula is a smooth extension to matrices near SO(3), on which
  /// ambient-coordinate solvers rely (kernels/lie_group/collocation_system.hpp evaluates log(gT^{-1} g(T))
  /// during Newton iterations, off the group). Validate user input with validate/from_matrix.
  static Tangent log(const Element& r);

  /// Written entry by entry, not with Eigen's comma initializer, so that GCC inlines it into the
  /// scheme's rates in a large unit (bench/README.md, "Solve speed against the start").
  static MatrixRep hat(const Tangent& v) {
    MatrixRep x;
    x(0, 0) = 0;
    x(0, 1) = -v.z();
    x(0, 2) = v.y();
    x(1, 0) = v.z();
    x(1, 1) = 0;
    x(1, 2) = -v.x();
    x(2, 0) = -v.y();
    x(2, 1) = v.x();
    x(2, 2) = 0;
    return x;
  }
  /// Reads the skew-symmetric part of x.
  static Tangent vee(const MatrixRep& x) { return Tangent(x(2, 1) - x(1, 2), x(0, 2) - x(2, 0), x(1, 0) - x(0, 1)) / 2; }
  static MatrixRep matrix(const Element& r) { return r; }

  static AlgebraMatrix Ad(const Element& r) { return r; }
  static AlgebraMatrix ad(const Tangent& v) { return hat(v); }

  static Element left_translate(const Element& r, const Tangent& v) { return r * hat(v); }
  static Element right_translate(const Element& r, const Tangent& v) { return hat(v) * r; }
  static Tangent left_trivialise(const Element& r, const Element& x) { return vee(r.transpose() * x); }
  static Tangent right_trivialise(const Element& r, const Element& x) { return vee(x * r.transpose()); }

  /// Throws std::invalid_argument naming `name` and the matrix unless r is finite, orthogonal
  /// and has determinant 1 within kDefaultTolerance.
  static void validate(const Element& r, std::string_view name);
  static void validate(const Element& r, std::string_view name, double tolerance);

  /// Validates m (within `tolerance`) and returns the nearest rotation (polar projection),
  /// so that input rounded to a few digits becomes an exact group element.
  static Element from_matrix(const Eigen::Matrix3d& m, double tolerance = kDefaultTolerance);

  /// The minimal rotation taking the direction of a to the direction of b: axis a x b, angle
  /// angle(a, b) (docs/paper-notes.md#convention-target-rotation). Identity when they are
  /// parallel; throws when a or b is zero or not finite, or when they are antiparallel (the
  /// rotation is not unique).
  static Element minimal_rotation(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
};

}  // namespace cartan::groups
