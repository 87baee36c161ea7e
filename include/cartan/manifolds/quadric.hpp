#pragma once
// The complete simply connected surfaces of constant curvature K = +1 and K = -1 as quadrics
// {q : <q, q> = K} in R^3 with <a, b> = a^T J b, J = diag(1, 1, K): the unit sphere S^2 (K = 1,
// Euclidean product) and the hyperbolic plane H^2 (K = -1, the upper sheet q_3 > 0 of the
// hyperboloid in Minkowski space), each with its Levi-Civita connection.
//
// On tangent vectors the Levi-Civita connection is the J-orthogonal projection of the ambient
// derivative, nabla_x Y = DY[x] + Gamma_q(x, Y) with Gamma_q(x, y) = K q <x, y> (for tangent Y,
// <q, Y> = 0 gives <q, DY[x]> = -<x, Y>). Hence R(x, y) z = K (<y, z> x - <x, z> y), T = 0, and
// nabla R = 0 (a symmetric space). Geodesics are the great circles / hyperbolas
// q cos_K(s) + x sin_K(s) for a unit tangent x, and parallel transport along one is the rotation
// (boost) of the plane (q, x) that moves q along it, fixing the normal direction
// (docs/general-connections.md#surfaces).

#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

#include "cartan/errors.hpp"
#include "cartan/manifolds/manifold.hpp"

namespace cartan::manifolds {

template <int Curvature>
class Quadric {
  static_assert(Curvature == 1 || Curvature == -1);
  static constexpr double K = Curvature;

 public:
  static constexpr int kDim = 2;
  static constexpr int kAmbientDim = 3;
  using Vector = Eigen::Vector3d;
  using Point = Eigen::Vector3d;
  using Frame = Eigen::Matrix<double, 3, 2>;
  using Operator = Eigen::Matrix3d;
  /// Tolerance of `validate` on |<q, q> - K| (relative to |q|^2).
  static constexpr double kPointTolerance = 1e-9;

  static std::string_view name() { return Curvature > 0 ? "sphere" : "hyperbolic-plane"; }
  static double curvature() { return K; }

  /// <a, b> = a^T J b.
  static double inner(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + K * a[2] * b[2]; }
  /// J, the metric on every tangent plane (positive definite there).
  static Operator metric(const Point&) { return Eigen::Vector3d(1, 1, K).asDiagonal(); }

  /// The J-orthogonal projection onto T_qQ: x - K q <q, x>.
  static Vector project_tangent(const Point& q, const Vector& x) { return x - K * inner(q, x) * q; }

  static Vector christoffel(const Point& q, const Vector& x, const Vector& y) { return K * inner(x, y) * q; }
  static Vector christoffel_derivative(const Point&, const Vector& z, const Vector& x, const Vector& y) {
    return K * inner(x, y) * z;
  }
  static Vector frame_bracket(const Vector&, const Vector&) { return Vector::Zero(); }

  /// The geodesic from q with initial velocity x (its tangent part) at s = 1.
  static Point step(const Point& q, const Vector& x) {
    const Vector xt = project_tangent(q, x);
    const double angle = std::sqrt(std::max(0.0, inner(xt, xt)));
    const Point p = cos_k(angle) * q + sin_k_over(angle) * xt;
    return p / std::sqrt(K * inner(p, p));  // back onto the quadric (rounding only)
  }

  /// The logarithm: the tangent x at a with step(a, x) = b. On S^2 the antipode -a is the cut
  /// locus of a, reached by every great circle: there x is pi times the first vector of
  /// tangent_basis(a) (one chosen geodesic, so that a geodesic guess between antipodal endpoints
  /// is a half great circle and a terminal residual there is pi, never 0).
  static Vector difference(const Point& a, const Point& b) {
    const Vector w = b - K * inner(a, b) * a;  // tangent part of b at a, of length sin_K(distance)
    const double s = std::sqrt(std::max(0.0, inner(w, w)));
    if (!(s > 0)) {
      if (Curvature > 0 && inner(a, b) < 0) return std::numbers::pi * Vector(tangent_basis(a).col(0));
      return Vector::Zero();
    }
    const double angle = Curvature > 0 ? std::atan2(s, inner(a, b)) : std::asinh(s);
    return (angle / s) * w;
  }

  /// Transport along the geodesic step(q, s x), s in [0, 1]: with u = x / |x| and c, s the
  /// cos_K, sin_K of |x|, P = I + (c - 1)(u u^T + K q q^T) J + K s (u q^T - q u^T) J.
  static Operator transport_along_step(const Point& q, const Vector& x) {
    const Vector xt = project_tangent(q, x);
    const double angle = std::sqrt(std::max(0.0, inner(xt, xt)));
    if (!(angle > 0)) return Operator::Identity();
    const Vector u = xt / angle;
    const Vector ju = metric(q) * u, jq = metric(q) * q;
    return Operator::Identity() + (cos_k(angle) - 1) * (u * ju.transpose() + K * q * jq.transpose()) +
           K * sin_k(angle) * (u * jq.transpose() - q * ju.transpose());
  }

  /// A J-orthonormal basis of T_qQ (positively oriented with the outward normal on S^2).
  static Frame tangent_basis(const Point& q) {
    int a = 0, b = 1;
    if constexpr (Curvature > 0) {  // the two axes least aligned with q
      int most = 0;
      for (int i = 1; i < 3; ++i) most = std::abs(q[i]) > std::abs(q[most]) ? i : most;
      a = most == 0 ? 1 : 0;
      b = most == 2 ? 1 : 2;
    }
    Frame e;
    e.col(0) = project_tangent(q, Vector::Unit(a));
    e.col(0) /= std::sqrt(inner(e.col(0), e.col(0)));
    e.col(1) = project_tangent(q, Vector::Unit(b));
    e.col(1) -= inner(e.col(0), e.col(1)) * e.col(0);
    e.col(1) /= std::sqrt(inner(e.col(1), e.col(1)));
    if (Curvature > 0 && e.col(0).cross(e.col(1)).dot(q) < 0) e.col(1) = -e.col(1);
    return e;
  }

  /// The frame at a towards b, the default frame of a problem from a to b (manifolds::default_frame):
  /// e1 the unit tangent at a along the minimal geodesic towards b, e2 = J (a x e1) (unit, tangent,
  /// J-orthogonal to e1; on S^2 (e1, e2, a) is right-handed). Empty where that geodesic does not
  /// give a direction: b = a, and on S^2 b = -a (every great circle is minimal).
  static std::optional<Frame> frame_towards(const Point& a, const Point& b) {
    const Vector towards = project_tangent(a, b);
    const double size = std::sqrt(std::max(0.0, inner(towards, towards)));
    if (!(size > 1e-12)) return std::nullopt;
    // Projected again once unit: with b near -a on S^2, |towards| is small and its rounding, of
    // order 1e-16 / |towards| relative, leaves a normal part in towards / size (1e-9 at 1e-7 from
    // -a, as large as GeneralProblem::validate allows a frame0); the second projection is exact
    // to rounding.
    const Vector e1 = project_tangent(a, Vector(towards / size));
    Frame e;
    e.col(0) = e1 / std::sqrt(inner(e1, e1));
    e.col(1) = metric(a) * a.cross(Vector(e.col(0)));
    return e;
  }

  /// Throws std::invalid_argument naming `where` unless q is finite and on the quadric
  /// (|<q, q> - K| <= kPointTolerance |q|^2; q_3 > 0 on H^2).
  static void validate(const Point& q, std::string_view where) {
    require_finite(q, where, "point");
    if (!(std::abs(inner(q, q) - K) <= kPointTolerance * q.squaredNorm()) || (Curvature < 0 && !(q[2] > 0))) {
      throw_invalid(where, "point", format_value(q),
                    Curvature > 0 ? "is not on the unit sphere (normalise it)"
                                  : "is not on the upper sheet q3 > 0 of q1^2 + q2^2 - q3^2 = -1");
    }
  }

  bool has_parallel_torsion_and_curvature() const { return true; }

 private:
  static double cos_k(double s) { return Curvature > 0 ? std::cos(s) : std::cosh(s); }
  static double sin_k(double s) { return Curvature > 0 ? std::sin(s) : std::sinh(s); }
  /// sin_K(s) / s, 1 at s = 0.
  static double sin_k_over(double s) { return s > 1e-8 ? sin_k(s) / s : 1 - K * s * s / 6; }
};

/// The unit sphere S^2 in R^3 with its Levi-Civita connection.
using Sphere = Quadric<1>;
/// The hyperbolic plane H^2 (hyperboloid model) with its Levi-Civita connection.
using HyperbolicPlane = Quadric<-1>;

/// The point of S^2 in the direction of x; throws std::invalid_argument if x is zero or not finite.
inline Eigen::Vector3d sphere_point(const Eigen::Vector3d& x, std::string_view where = "sphere_point") {
  require_finite(x, where, "point");
  if (!(x.norm() > 0)) throw_invalid(where, "point", format_value(x), "must be nonzero");
  return x.normalized();
}

/// The point of H^2 above (x1, x2): (x1, x2, sqrt(1 + x1^2 + x2^2)).
inline Eigen::Vector3d hyperbolic_point(double x1, double x2) {
  require_finite(x1, "hyperbolic_point", "x1");
  require_finite(x2, "hyperbolic_point", "x2");
  return {x1, x2, std::sqrt(1 + x1 * x1 + x2 * x2)};
}

}  // namespace cartan::manifolds
