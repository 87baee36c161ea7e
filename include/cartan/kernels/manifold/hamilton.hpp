#pragma once
// The global Hamilton equations with a linear connection (eq:HE-1, prop:hamilton-principle-phase)
// on a manifold in a chart (manifolds::ChartWithConnection: Euclidean<m>, Chart<m>, the quadrics
// through manifolds/stereographic.hpp), for any connection nabla_{d_i} d_j = Gamma^k_ij d_k,
// torsion T^k_ij = Gamma^k_ij - Gamma^k_ji allowed:
//   q' = d_p H,                                   (eq:vert-grad)
//   D/dt p + p(i_{q'} T) = -d^nabla_q H,           (eq:hor-diff-2)
// with, in the chart (i_{q'} T = T(q', .), as in eq:variation-der and eq:EL-1),
//   (D/dt p)_i       = p_i' - Gamma^k_ji q'^j p_k       -> `covariant` = -Gamma^k_ji q'^j p_k,
//   p(T(q', d_i))    = (Gamma^k_ji - Gamma^k_ij) q'^j p_k -> `torsion`,
//   (d^nabla_q H)_i  = dH/dq^i + Gamma^k_ij p_k dH/dp_j  -> `horizontal`.
// Each term depends on the connection; their sum does not: p_i' = -dH/dq^i, the paper's remark
// after prop:hamilton-principle-phase ("regardless of the linear connection used"). The terms are
// evaluated as written, so the tests check each against its definition and measure the
// cancellation (docs/paper-notes.md#erratum-8 for the paper's T*M coefficients).
//
// Integration: classical RK4 on the chart coordinates (q, p), global error O(h^4).

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <concepts>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/manifolds/bundle.hpp"

namespace cartan::general {

/// A Hamiltonian H(t, q, p) on T*Q in chart coordinates:
///   value(t, q, p)           H
///   velocity(t, q, p)        d_p H = dH/dp_i d_i (eq:vert-grad), the q' of eq:HE-1
///   point_gradient(t, q, p)  dH/dq^i at fixed p_i (chart-dependent; the horizontal differential,
///                            computed from it and the connection, is not).
template <class H, class M>
concept ChartHamiltonian =
    manifolds::ChartWithConnection<M> &&
    requires(const H& h, double t, const manifolds::PointOf<M>& q, const manifolds::VectorOf<M>& p) {
      { h.value(t, q, p) } -> std::convertible_to<double>;
      { h.velocity(t, q, p) } -> std::convertible_to<manifolds::VectorOf<M>>;
      { h.point_gradient(t, q, p) } -> std::convertible_to<manifolds::VectorOf<M>>;
    };

/// H = 1/2 p^T g(q)^{-1} p + V(q), the Legendre transform of L = 1/2 q'^T g(q) q' - V(q)
/// (p = g q', `momentum`). g is a field of symmetric
/// positive definite matrices (a Chart's metric field, or a constant mass matrix). dH/dq uses
/// dg/dq^i by the fourth-order central difference with step eps^(1/5) max(1, |q|) (error about
/// eps^(4/5) ~ 3e-13 relative; exact for a constant g).
template <manifolds::ChartWithConnection M>
class KineticPotentialHamiltonian {
 public:
  using Point = manifolds::PointOf<M>;
  using Vector = manifolds::VectorOf<M>;
  using Operator = manifolds::OperatorOf<M>;
  using MetricField = std::function<Operator(const Point&)>;
  using Potential = std::function<double(const Point&)>;
  using PotentialGradient = std::function<Vector(const Point&)>;

  /// Throws std::invalid_argument if the metric field is empty or if exactly one of V and its
  /// gradient is given.
  explicit KineticPotentialHamiltonian(MetricField metric, Potential potential = {}, PotentialGradient gradient = {})
      : metric_(std::move(metric)), potential_(std::move(potential)), gradient_(std::move(gradient)) {
    if (!metric_) throw_invalid("KineticPotentialHamiltonian", "metric", "(empty)", "must be a function of the point");
    if (static_cast<bool>(potential_) != static_cast<bool>(gradient_)) {
      throw_invalid("KineticPotentialHamiltonian", "potential", potential_ ? "given" : "absent",
                    "and its gradient must be given together");
    }
  }

  /// A constant mass matrix g.
  static KineticPotentialHamiltonian constant(const Operator& mass, Potential potential = {}, PotentialGradient gradient = {}) {
    require_finite(mass, "KineticPotentialHamiltonian::constant", "mass");
    return KineticPotentialHamiltonian([mass](const Point&) { return mass; }, std::move(potential), std::move(gradient));
  }

  Operator metric(const Point& q) const { return metric_(q); }
  double potential(const Point& q) const { return potential_ ? potential_(q) : 0.0; }
  /// The Legendre map of L: p = g(q) q'.
  Vector momentum(const Point& q, const Vector& qdot) const { return metric_(q) * qdot; }

  double value(double t, const Point& q, const Vector& p) const { return 0.5 * p.dot(velocity(t, q, p)) + potential(q); }
  Vector velocity(double, const Point& q, const Vector& p) const {
    const Eigen::LDLT<Operator> factor(metric_(q));
    if (factor.info() != Eigen::Success || !(factor.vectorD().minCoeff() > 0)) {
      throw ModelError("KineticPotentialHamiltonian: the metric is not positive definite at q = " + format_value(q));
    }
    return factor.solve(p);
  }
  /// dH/dq^i = -1/2 v^T (dg/dq^i) v + dV/dq^i with v = g^{-1} p.
  Vector point_gradient(double t, const Point& q, const Vector& p) const {
    const Vector v = velocity(t, q, p);
    const double s = std::pow(std::numeric_limits<double>::epsilon(), 0.2) * std::max(1.0, q.norm());
    Vector out = gradient_ ? Vector(gradient_(q)) : Vector::Zero();
    for (int i = 0; i < M::kDim; ++i) {
      const auto at = [&](double a) { return Operator(metric_(Point(q + a * Vector::Unit(i)))); };
      const Operator dg = (8 * (at(s) - at(-s)) - (at(2 * s) - at(-2 * s))) / (12 * s);
      out[i] -= 0.5 * v.dot(dg * v);
    }
    return out;
  }

 private:
  MetricField metric_;
  Potential potential_;
  PotentialGradient gradient_;
};

/// The terms of eq:HE-1 at one point of T*Q (header comment), all in chart components.
template <manifolds::ChartWithConnection M>
struct HamiltonTerms {
  using Vector = manifolds::VectorOf<M>;
  Vector velocity;    ///< d_p H, the q' of the first line
  Vector covariant;   ///< -Gamma^k_ji q'^j p_k: D/dt p = p' + covariant
  Vector torsion;     ///< p(i_{q'} T)_i = p_k T^k(q', d_i)
  Vector horizontal;  ///< d^nabla_q H (eq:hor-diff-2)

  /// The second line of eq:HE-1 solved for p'.
  Vector momentum_rate() const { return -horizontal - torsion - covariant; }
};

template <manifolds::ChartWithConnection M, ChartHamiltonian<M> H>
HamiltonTerms<M> hamilton_terms(const M& manifold, const H& hamiltonian, double t, const manifolds::PointOf<M>& q,
                                const manifolds::VectorOf<M>& p) {
  using Vector = manifolds::VectorOf<M>;
  HamiltonTerms<M> out;
  out.velocity = hamiltonian.velocity(t, q, p);
  // christoffel_operator(q, q')(k, i) = Gamma^k_ji q'^j.
  out.covariant = -manifolds::christoffel_operator(manifold, q, out.velocity).transpose() * p;
  for (int i = 0; i < M::kDim; ++i) {
    out.torsion[i] = p.dot(manifolds::torsion(manifold, q, out.velocity, Vector(Vector::Unit(i))));
  }
  out.horizontal = manifolds::cotangent_horizontal_differential(manifold, q, p, Vector(hamiltonian.point_gradient(t, q, p)),
                                                                out.velocity);
  return out;
}

/// The nodes t_k = k h of a solution of eq:HE-1 in the chart.
template <manifolds::ChartWithConnection M>
struct HamiltonTrajectory {
  std::vector<double> t;
  std::vector<manifolds::PointOf<M>> q;
  std::vector<manifolds::VectorOf<M>> p;
};

/// Integrates eq:HE-1 for `manifold`'s connection over [0, T] in `steps` classical RK4 steps on
/// the chart coordinates from (q0, p0). Throws std::invalid_argument for T not positive, steps < 1,
/// q0 outside the chart (manifold.validate) or p0 not finite.
template <manifolds::ChartWithConnection M, ChartHamiltonian<M> H>
HamiltonTrajectory<M> hamilton(const M& manifold, const H& hamiltonian, const manifolds::PointOf<M>& q0,
                               const manifolds::VectorOf<M>& p0, double T, int steps) {
  using Vector = manifolds::VectorOf<M>;
  require_finite(T, "general::hamilton", "T");
  if (!(T > 0)) throw_invalid("general::hamilton", "T", format_value(T), "must be positive");
  if (steps < 1) throw_invalid("general::hamilton", "steps", std::to_string(steps), "must be at least 1");
  manifold.validate(q0, "q0");
  require_finite(p0, "general::hamilton", "p0");
  struct Rate {
    Vector q, p;
  };
  const auto rate = [&](double t, const Vector& q, const Vector& p) {
    const HamiltonTerms<M> terms = hamilton_terms(manifold, hamiltonian, t, q, p);
    return Rate{terms.velocity, terms.momentum_rate()};
  };
  const double h = T / steps;
  HamiltonTrajectory<M> out;
  out.t.reserve(static_cast<std::size_t>(steps) + 1);
  out.q.reserve(out.t.capacity());
  out.p.reserve(out.t.capacity());
  Vector q = q0, p = p0;
  for (int k = 0;; ++k) {
    const double t = k * h;
    out.t.push_back(t), out.q.push_back(q), out.p.push_back(p);
    if (k == steps) break;
    const Rate k1 = rate(t, q, p);
    const Rate k2 = rate(t + h / 2, Vector(q + h / 2 * k1.q), Vector(p + h / 2 * k1.p));
    const Rate k3 = rate(t + h / 2, Vector(q + h / 2 * k2.q), Vector(p + h / 2 * k2.p));
    const Rate k4 = rate(t + h, Vector(q + h * k3.q), Vector(p + h * k3.p));
    q += h / 6 * (k1.q + 2 * k2.q + 2 * k3.q + k4.q);
    p += h / 6 * (k1.p + 2 * k2.p + 2 * k3.p + k4.p);
  }
  return out;
}

/// The phase-space action of prop:hamilton-principle-phase, int (p(q') - H) dt, of the discrete
/// curve (t_k, q_k, p_k) by the midpoint rule: sum_k [pbar_k . (q_{k+1} - q_k) - dt_k H(tbar_k,
/// qbar_k, pbar_k)], bars the means of the two nodes (second order in the largest dt_k for a
/// smooth curve). Throws std::invalid_argument unless t, q, p have the same size >= 2.
template <manifolds::ChartWithConnection M, ChartHamiltonian<M> H>
double phase_space_action(const H& hamiltonian, const HamiltonTrajectory<M>& x) {
  const std::size_t n = x.t.size();
  if (n < 2 || x.q.size() != n || x.p.size() != n) {
    throw_invalid("phase_space_action", "trajectory", std::to_string(n) + " times", "needs >= 2 times and q, p at each");
  }
  double action = 0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const manifolds::VectorOf<M> q = (x.q[k] + x.q[k + 1]) / 2, p = (x.p[k] + x.p[k + 1]) / 2;
    const double dt = x.t[k + 1] - x.t[k];
    action += p.dot(x.q[k + 1] - x.q[k]) - dt * hamiltonian.value((x.t[k] + x.t[k + 1]) / 2, q, p);
  }
  return action;
}

}  // namespace cartan::general
