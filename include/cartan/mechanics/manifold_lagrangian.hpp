#pragma once
// Lagrangians l(t, q, v) of the general transported-velocity problem (paper eq:action-conn-dep):
// q a point of a manifold with a connection, v in R^m the components of the transported velocity
// in the frame chosen at q0. The interface mirrors mechanics::ReducedLagrangian:
//   value(t, q, v)           l
//   momentum(t, q, v)        mu = dl/dv in R^m (the paper's delta_{v^i} l)
//   velocity(t, q, mu)       the inverse Legendre map
//   point_gradient(t, q, v)  an ambient covector zeta in R^d with zeta . x = d/de l(t, step(q, e x), v)
//                            for tangent x (v held fixed): delta_{q^i} l = zeta . e_i(t).
// Built in: KineticPotential, l = 1/2 v^T A v - V(q).

#include <Eigen/Cholesky>
#include <concepts>
#include <functional>

#include "cartan/errors.hpp"
#include "cartan/manifolds/derivatives.hpp"
#include "cartan/manifolds/group_manifold.hpp"
#include "cartan/manifolds/manifold.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"

namespace cartan::general {

template <class L, class M>
concept ManifoldLagrangian =
    manifolds::ManifoldWithConnection<M> &&
    requires(const L& l, double t, const manifolds::PointOf<M>& q, const manifolds::ComponentsOf<M>& v) {
      { l.value(t, q, v) } -> std::convertible_to<double>;
      { l.momentum(t, q, v) } -> std::convertible_to<manifolds::ComponentsOf<M>>;
      { l.velocity(t, q, v) } -> std::convertible_to<manifolds::ComponentsOf<M>>;
      { l.point_gradient(t, q, v) } -> std::convertible_to<manifolds::VectorOf<M>>;
    };

/// Second derivatives of a Lagrangian with the point perturbed along pieces, q_e = step(q, e dq)
/// (manifolds/derivatives.hpp), for the tangent-linear sweep (manifold_lagrangian_hessian.hpp).
template <manifolds::ManifoldWithConnection M>
struct LagrangianHessian {
  static constexpr int m = M::kDim, d = M::kAmbientDim;
  Eigen::Matrix<double, m, m> momentum_v;  ///< d mu / dv
  Eigen::Matrix<double, m, d> momentum_q;  ///< d mu / dq (on tangent vectors at q)
  Eigen::Matrix<double, d, m> gradient_v;  ///< d zeta / dv (zeta the point gradient)
  Eigen::Matrix<double, d, d> gradient_q;  ///< d zeta / dq

  bool all_finite() const {
    return momentum_v.allFinite() && momentum_q.allFinite() && gradient_v.allFinite() && gradient_q.allFinite();
  }
};

/// A point (t, q, v) where general::check_lagrangian compares a Lagrangian's callbacks
/// (manifold_check_lagrangian.hpp).
template <manifolds::ManifoldWithConnection M>
struct ManifoldLagrangianSample {
  double t = 0;
  manifolds::PointOf<M> q;
  manifolds::ComponentsOf<M> v;
};

/// l = 1/2 v^T A v - V(q) with a constant symmetric positive definite A (the "inertia" or "mass"
/// in frame components) and an optional potential V with its ambient gradient. Its energy
/// 1/2 v^T A v + V(q) is conserved along solutions for every connection
/// (docs/general-connections.md#energy).
template <manifolds::ManifoldWithConnection M>
class KineticPotential {
 public:
  using Point = manifolds::PointOf<M>;
  using Vector = manifolds::VectorOf<M>;
  using Components = manifolds::ComponentsOf<M>;
  using Inertia = manifolds::ComponentMatrixOf<M>;
  using Potential = std::function<double(const Point&)>;
  using PotentialGradient = std::function<Vector(const Point&)>;

  /// Throws std::invalid_argument naming A unless it is finite, symmetric and positive definite,
  /// or if exactly one of V and its gradient is given.
  explicit KineticPotential(const Inertia& inertia, Potential potential = {}, PotentialGradient gradient = {})
      : inertia_(inertia), factor_(inertia), potential_(std::move(potential)), gradient_(std::move(gradient)) {
    require_finite(inertia, "KineticPotential", "inertia");
    const double scale = inertia.cwiseAbs().maxCoeff();
    if (!((inertia - inertia.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale) || factor_.info() != Eigen::Success ||
        !(factor_.vectorD().minCoeff() > 1e-14 * scale)) {
      throw_invalid("KineticPotential", "inertia", format_value(inertia), "must be symmetric positive definite");
    }
    if (static_cast<bool>(potential_) != static_cast<bool>(gradient_)) {
      throw_invalid("KineticPotential", "potential", potential_ ? "given" : "absent",
                    "and its gradient must be given together");
    }
  }

  /// V(q) = c . q for points that are vectors (a uniform field: gravity G z on S^2 is c = (0, 0, G)).
  static KineticPotential with_linear_potential(const Inertia& inertia, const Vector& c) {
    require_finite(c, "KineticPotential::with_linear_potential", "c");
    return KineticPotential(inertia, [c](const Point& q) { return c.dot(q); }, [c](const Point&) { return c; });
  }

  const Inertia& inertia() const { return inertia_; }
  /// 1/2 v^T A v is the same in every orthonormal frame where A is a multiple of the identity
  /// (mechanics::frame_invariant_of); V(q) does not see the frame.
  bool frame_invariant() const {
    return (inertia_ - inertia_(0, 0) * Inertia::Identity()).cwiseAbs().maxCoeff() == 0;
  }
  double potential(const Point& q) const { return potential_ ? potential_(q) : 0.0; }

  double value(double, const Point& q, const Components& v) const { return 0.5 * v.dot(inertia_ * v) - potential(q); }
  Components momentum(double, const Point&, const Components& v) const { return inertia_ * v; }
  Components velocity(double, const Point&, const Components& mu) const { return factor_.solve(mu); }
  Vector point_gradient(double, const Point& q, const Components&) const {
    return gradient_ ? Vector(-gradient_(q)) : Vector::Zero();
  }
  /// Exact but for d zeta / dq = -D grad V, a central difference of the potential's gradient.
  template <class Manifold>
  LagrangianHessian<M> hessian(const Manifold& manifold, double, const Point& q, const Components&) const {
    LagrangianHessian<M> h;
    h.momentum_v = inertia_;
    h.momentum_q.setZero();
    h.gradient_v.setZero();
    h.gradient_q.setZero();
    if (gradient_) h.gradient_q = -manifolds::point_derivative(manifold, q, [&](const Point& p) { return Vector(gradient_(p)); });
    return h;
  }
  /// mu = A v with A constant; the point gradient -grad V does not depend on v, and is 0 without V.
  mechanics::RuntimeHessianStructure hessian_structure() const { return {true, true, !gradient_}; }
  /// 1/2 v^T A v + V(q).
  double energy(const Point& q, const Components& v) const { return 0.5 * v.dot(inertia_ * v) + potential(q); }

 private:
  Inertia inertia_;
  Eigen::LDLT<Inertia> factor_;
  Potential potential_;
  PotentialGradient gradient_;
};

/// A left-reduced Lagrangian l(t, g, v) (mechanics::ReducedLagrangian) as a Lagrangian of the
/// general problem on GroupManifold<G>: with the algebra basis as the frame at g0 = the identity of
/// the trivialisation, v is the same transported velocity and the left-trivialised group gradient
/// zeta is the point gradient (delta_{q^i} l = zeta . e_i(t), e_i(t) left-trivialised). Every model
/// of the Lie-group solvers then runs under any left-invariant connection.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
struct OnGroupManifold {
  L lagrangian;

  double value(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return lagrangian.value(t, g, v);
  }
  groups::CovectorOf<G> momentum(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return lagrangian.momentum(t, g, v);
  }
  groups::TangentOf<G> velocity(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return lagrangian.velocity(t, g, mu);
  }
  groups::CovectorOf<G> point_gradient(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return lagrangian.group_gradient(t, g, v);
  }
  /// The model's own second derivatives (mechanics::lagrangian_hessian: analytic where it has
  /// them): the same perturbation g exp(e gamma) on every GroupManifold<G>.
  LagrangianHessian<manifolds::GroupManifold<G>> hessian(const manifolds::GroupManifold<G>&, double t,
                                                         const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    const mechanics::LagrangianHessian<G> h = mechanics::lagrangian_hessian<G>(lagrangian, t, g, v);
    return {h.momentum_v, h.momentum_g, h.gradient_v, h.gradient_g};
  }
  /// The model's (its point gradient is its group gradient).
  mechanics::RuntimeHessianStructure hessian_structure() const { return mechanics::hessian_structure_of(lagrangian); }
};

}  // namespace cartan::general
