#pragma once
// A manifold given in one chart: points are coordinates q in an open set of R^m and the connection
// is any field of Christoffel symbols q -> Gamma^k_ij(q), nabla_{e_i} e_j = Gamma^k_ij e_k on the
// coordinate fields (torsion where Gamma^k_ij != Gamma^k_ji). This is how a user brings a manifold
// and connection of their own (the Poincare half-plane, a surface in local coordinates, ...),
// from C++ or from Python (cartan.Chart).
//
// Pieces are the coordinate lines step(q, x) = q + x; parallel transport along one solves
// y' = -Gamma_{q + s x}(x, y) on [0, 1] by n classical Runge–Kutta steps, n = max(4, ceil(128 a))
// with a = |Gamma_q(x, .)| (Frobenius), so that a / n <= 1/128 and each step's relative error,
// about (a / n)^5 / 120, is below 3e-13: about 1e-11 in all for a of order 1, and rounding at the
// schemes' step sizes, where a is of order h omega (tests/manifolds checks it against a 200-step
// integration).
// D Gamma is a central difference (geometry.hpp). An optional metric field g(q) makes the chart a
// MetricManifold (the tests then check that transport preserves it: a Levi-Civita Gamma), and
// its default frame (tangent_basis) orthonormal in it.
// The domain: `validate` rejects points where Gamma (or g) is not finite, with the callback's own
// exception passing through, so a field may throw outside its domain (e.g. y <= 0 on the half-plane).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "cartan/errors.hpp"
#include "cartan/manifolds/derivatives.hpp"

namespace cartan::manifolds {

template <int Dim>
class Chart {
 public:
  static_assert(Dim >= 1);
  static constexpr int kDim = Dim;
  static constexpr int kAmbientDim = Dim;
  using Vector = Eigen::Matrix<double, Dim, 1>;
  using Point = Vector;
  using Frame = Eigen::Matrix<double, Dim, Dim>;
  using Operator = Eigen::Matrix<double, Dim, Dim>;
  /// coefficients[i](k, j) = Gamma^k_ij (as Euclidean<Dim>::Coefficients).
  using Coefficients = std::array<Operator, Dim>;
  using ChristoffelField = std::function<Coefficients(const Point&)>;
  using MetricField = std::function<Operator(const Point&)>;

  /// `parallel`: the caller declares nabla T = nabla R = 0 (e.g. a constant-curvature Levi-Civita
  /// connection), which lets the solver compute the frame components once; declare it only when
  /// true (the default false is always correct, and slower). Throws std::invalid_argument if the
  /// Christoffel field is empty.
  explicit Chart(ChristoffelField christoffel, MetricField metric = {}, std::string name = "chart", bool parallel = false)
      : gamma_(std::move(christoffel)), metric_(std::move(metric)), name_(std::move(name)), parallel_(parallel) {
    if (!gamma_) throw_invalid("Chart", "christoffel", "(empty)", "must be a function of the point");
  }

  std::string_view name() const { return name_; }
  Coefficients coefficients(const Point& q) const { return gamma_(q); }

  Vector christoffel(const Point& q, const Vector& x, const Vector& y) const { return operator_of(gamma_(q), x) * y; }
  Vector frame_bracket(const Vector&, const Vector&) const { return Vector::Zero(); }
  Point step(const Point& q, const Vector& x) const { return q + x; }
  Vector difference(const Point& a, const Point& b) const { return b - a; }
  StepJacobians<Chart> step_jacobians(const Point&, const Vector&) const {
    return {Operator::Identity(), Operator::Identity()};
  }
  /// Transport along q + s x, s in [0, 1]: RK4 on Y' = -A(s) Y, A(s) = Gamma_{q + s x}(x, .).
  /// Each step evaluates the field twice (A at the midpoint and the end; the start is the
  /// previous step's end), which matters when it is a Python callable.
  Operator transport_along_step(const Point& q, const Vector& x) const {
    const auto field_along = [&](double s) { return operator_of(gamma_(q + s * x), x); };
    Operator a = field_along(0.0);
    const double size = a.norm();
    const int steps = std::isfinite(size) ? static_cast<int>(std::clamp(std::ceil(128 * size), 4.0, 4096.0)) : 4;
    const double h = 1.0 / steps;
    Operator y = Operator::Identity();
    for (int k = 0; k < steps; ++k) {
      const double s = k * h;
      const Operator a_mid = field_along(s + h / 2), a_end = field_along(s + h);
      const Operator k1 = -a * y, k2 = -a_mid * (y + h / 2 * k1), k3 = -a_mid * (y + h / 2 * k2), k4 = -a_end * (y + h * k3);
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      a = a_end;
    }
    return y;
  }
  /// The coordinate directions, orthonormalised in the metric when the chart has one (Gram-Schmidt
  /// in g, i.e. E = R^-1 with g = R^T R its Cholesky factor, so that E^T g E = I: the frame the
  /// transported velocity's components are taken in, so l = 1/2 |v|^2 is 1/2 g(q', q')); without a
  /// metric the coordinate basis. Throws std::invalid_argument where the metric is not symmetric
  /// positive definite.
  Frame tangent_basis(const Point& q) const {
    if (!metric_) return Frame::Identity();
    const Operator g = metric_(q);
    const double size = g.cwiseAbs().maxCoeff();
    const Eigen::LLT<Operator> cholesky(g);
    if (!g.allFinite() || !((g - g.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * size) ||
        cholesky.info() != Eigen::Success) {
      throw_invalid("Chart.tangent_basis", "metric at " + format_value(q), format_value(g),
                    "is not symmetric positive definite");
    }
    return cholesky.matrixU().solve(Frame::Identity());
  }
  bool has_parallel_torsion_and_curvature() const { return parallel_; }
  std::optional<Operator> metric(const Point& q) const {
    return metric_ ? std::optional<Operator>(metric_(q)) : std::nullopt;
  }
  /// q finite, and the fields finite at q (in the chart's domain).
  void validate(const Point& q, std::string_view where) const {
    require_finite(q, where, "point");
    const Coefficients c = gamma_(q);
    for (const Operator& m : c) {
      if (!m.allFinite()) throw_invalid(where, "point", format_value(q), "is outside the chart (Christoffel symbols not finite)");
    }
    if (metric_ && !metric_(q).allFinite()) {
      throw_invalid(where, "point", format_value(q), "is outside the chart (metric not finite)");
    }
  }

 private:
  static Operator operator_of(const Coefficients& c, const Vector& x) {
    Operator m = Operator::Zero();
    for (int i = 0; i < Dim; ++i) m += x[i] * c[i];
    return m;
  }

  ChristoffelField gamma_;
  MetricField metric_;
  std::string name_;
  bool parallel_;
};

/// The Poincare half-plane {(x, y): y > 0} with g = (dx^2 + dy^2) / y^2 and its Levi-Civita
/// connection (curvature -1, so nabla R = 0): Gamma^x_xy = Gamma^x_yx = Gamma^y_yy = -1/y,
/// Gamma^y_xx = 1/y. Points with y <= 0 are rejected.
inline Chart<2> poincare_half_plane() {
  const auto symbols = [](const Eigen::Vector2d& q) {
    const double inv = q.y() > 0 ? 1 / q.y() : std::numeric_limits<double>::quiet_NaN();
    Chart<2>::Coefficients c;
    c[0] << 0, -inv, inv, 0;   // i = x: Gamma^x_xj (row 0), Gamma^y_xj (row 1)
    c[1] << -inv, 0, 0, -inv;  // i = y: Gamma^x_yj, Gamma^y_yj
    return c;
  };
  const auto metric = [](const Eigen::Vector2d& q) -> Eigen::Matrix2d {
    return Eigen::Matrix2d::Identity() / (q.y() * q.y());
  };
  return Chart<2>(symbols, metric, "poincare-half-plane", true);
}

}  // namespace cartan::manifolds
