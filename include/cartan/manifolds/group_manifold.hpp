#pragma once
// A Lie group with any left-invariant connection, given by its bilinear map alpha
// (connections/invariant_connection.hpp), as a manifold with a connection: points are group
// elements, vectors are left-trivialised (x at g stands for g x), and the Christoffel map is
// alpha itself (eq:cov-curve-left: D/dt (g y) = g (y' + alpha(u, y))). The constant fields are
// the left-invariant ones, with bracket [x, y]. Along the piece g exp(s x) the transport equation
// y' = -alpha(x, y) has constant coefficients: transport_along_step is exp(-alpha(x, .)).
//
// Instances: `cartan_schouten(lambda)` (alpha = lambda ad, CS-conn; nabla T = nabla R = 0: the
// existing solvers' fast path), `levi_civita(metric)` for a left-invariant metric I on the algebra
// (Koszul: alpha(x, y) = 1/2 ([x, y] - I^{-1}(ad_x^T I y + ad_y^T I x)); not bi-invariant in
// general, and then nabla R != 0), and any `InvariantConnection` with the left side.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

#include "cartan/connections/cartan_schouten.hpp"
#include "cartan/connections/connection_kind.hpp"
#include "cartan/connections/invariant_connection.hpp"
#include "cartan/groups/exp_jacobian.hpp"
#include "cartan/manifolds/constant_connection.hpp"
#include "cartan/manifolds/derivatives.hpp"

namespace cartan::manifolds {

template <groups::LieGroup G>
class GroupManifold {
 public:
  static constexpr int kDim = G::kDim;
  static constexpr int kAmbientDim = G::kDim;
  using Group = G;
  using Point = groups::ElementOf<G>;
  using Vector = groups::TangentOf<G>;
  using Frame = groups::AlgebraMatrixOf<G>;
  using Operator = groups::AlgebraMatrixOf<G>;
  /// alpha and exp(-alpha(x, .)) do not depend on g in the left trivialisation (derivatives.hpp).
  static constexpr bool kPointIndependentConnection = true;

  /// Throws std::invalid_argument unless the connection is left-invariant.
  explicit GroupManifold(const connections::InvariantConnection<G>& connection,
                         std::optional<Operator> metric = std::nullopt)
      : connection_(connection), metric_(std::move(metric)) {
    if (connection.side() != groups::Side::Left) {
      throw_invalid("GroupManifold", "connection.side", "right",
                    "must be left: give a right-invariant connection by its left bilinear map");
    }
    parallel_ = constant_coefficients_have_parallel_torsion_and_curvature(*this, G::identity());
  }

  /// The Cartan–Schouten connection of parameter lambda (CS-conn).
  static GroupManifold cartan_schouten(double lambda) {
    GroupManifold m(connections::cartan_schouten<G>(lambda));
    m.lambda_ = lambda;
    return m;
  }

  /// The Levi-Civita connection of the left-invariant metric <x, y> = x^T I y. Throws
  /// std::invalid_argument naming the matrix unless I is finite, symmetric and positive definite.
  static GroupManifold levi_civita(const Operator& metric) {
    require_finite(metric, "GroupManifold::levi_civita", "metric");
    const double scale = metric.cwiseAbs().maxCoeff();
    if (!((metric - metric.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale) ||
        Eigen::LLT<Operator>(metric).info() != Eigen::Success) {
      throw_invalid("GroupManifold::levi_civita", "metric", format_value(metric),
                    "must be symmetric positive definite");
    }
    const Eigen::LLT<Operator> factor(metric);
    const auto alpha = [&](const Vector& x, const Vector& y) -> Vector {
      const Vector asym = G::ad(x).transpose() * (metric * y) + G::ad(y).transpose() * (metric * x);
      return 0.5 * (groups::bracket<G>(x, y) - factor.solve(asym));
    };
    return GroupManifold(connections::InvariantConnection<G>::from_bilinear(groups::Side::Left, alpha), metric);
  }

  /// The connection alpha(e_i, e_j) = sum_k alpha[(i n + j) n + k] e_k of its n^3 coefficients
  /// (the CLI's alpha file and Python's (n, n, n) array, in (i, j, k) order). Throws
  /// std::invalid_argument naming them unless there are n^3 finite numbers.
  static GroupManifold coefficients(std::span<const double> alpha) {
    constexpr std::size_t n = kDim;
    if (alpha.size() != n * n * n) {
      throw_invalid("GroupManifold::coefficients", "alpha", "(" + std::to_string(alpha.size()) + " numbers)",
                    "must have n^3 = " + std::to_string(n * n * n) + " numbers");
    }
    typename connections::InvariantConnection<G>::Coefficients c;  // c[i](k, j): column j is alpha(e_i, e_j)
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t k = 0; k < n; ++k) {
          const double a = alpha[(i * n + j) * n + k];
          require_finite(a, "GroupManifold::coefficients", "alpha");
          c[i](static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = a;
        }
      }
    }
    return GroupManifold(connections::InvariantConnection<G>(groups::Side::Left, c));
  }

  static std::string_view name() { return G::name(); }
  const connections::InvariantConnection<G>& connection() const { return connection_; }
  /// lambda when built by cartan_schouten (the existing solvers' problem), else empty.
  std::optional<double> cartan_schouten_lambda() const { return lambda_; }
  /// The left-invariant metric the connection preserves, when built by levi_civita.
  std::optional<Operator> metric(const Point&) const { return metric_; }

  Vector christoffel(const Point&, const Vector& x, const Vector& y) const { return connection_.nabla(x, y); }
  Vector christoffel_derivative(const Point&, const Vector&, const Vector&, const Vector&) const {
    return Vector::Zero();
  }
  Vector frame_bracket(const Vector& x, const Vector& y) const { return groups::bracket<G>(x, y); }
  Point step(const Point& g, const Vector& x) const { return G::compose(g, G::exp(x)); }
  Vector difference(const Point& a, const Point& b) const { return groups::log_between<G>(a, b); }
  /// The derivative of the stored element along g exp(s x) at s = 0: d(L_g)_e x.
  Point point_velocity(const Point& g, const Vector& x) const { return G::left_translate(g, x); }
  /// exp(-alpha(x, .)); for Cartan–Schouten's alpha = lambda ad, exp(-lambda ad_x) = Ad(exp(-lambda x)):
  /// the group's closed forms (Rodrigues on SO(3)) instead of a matrix exponential.
  Operator transport_along_step(const Point&, const Vector& x) const {
    if (lambda_) return G::Ad(G::exp(Vector(-*lambda_ * x)));
    return Operator(-connection_.nabla_operator(x)).exp();
  }
  /// (g exp(e a)) exp(x) = g exp(x) exp(e Ad(exp(-x)) a), exp(x + e b) = exp(x) exp(e J_r(x) b).
  StepJacobians<GroupManifold> step_jacobians(const Point&, const Vector& x) const {
    return {G::Ad(G::exp(Vector(-x))), groups::right_jacobian<G>(x)};
  }
  Operator transport_along_step_derivative(const Point&, const Vector& x, const Vector& dx) const {
    return exp_derivative<kDim>(-connection_.nabla_operator(x), -connection_.nabla_operator(dx));
  }
  Frame tangent_basis(const Point&) const { return Frame::Identity(); }
  void validate(const Point& g, std::string_view where) const { G::validate(g, where); }
  bool has_parallel_torsion_and_curvature() const { return parallel_; }

 private:
  connections::InvariantConnection<G> connection_;
  std::optional<Operator> metric_;
  std::optional<double> lambda_;
  bool parallel_ = false;
};

}  // namespace cartan::manifolds
