#pragma once
// Horizontal differentials on fibre bundles (paper §2 "Horizontal differentials").
//
// A vector bundle E -> M of rank r over an n-dimensional base, in local coordinates (x^i, u^alpha),
// with a linear Ehresmann connection: its connection coefficients (paper, before eq:hrz-lift-vec)
// are linear in the fibre coordinate,
//   Gamma_i^alpha(x, u) = A_i(x)^alpha_beta u^beta,
// so the horizontal lift of d/dx^i is H_i = d/dx^i - (A_i u)^alpha d/du^alpha, and the parallel
// transport of u along a base curve gamma solves u' = -gamma'^i A_i(gamma) u (eq:hrz-lift-curve).
// The horizontal differential of F in C^inf(E) (eq:hor-diff-local) is
//   d^Gamma_x F = (dF/dx^i - Gamma_i^alpha dF/du^alpha) dx^i,
// and lem:horizontal-differential (hor-diff-curve) evaluates it as d/de F(transport of u to e).
//
// Instances from a chart with a linear connection nabla_{d_i} d_j = Gamma^k_ij d_k:
//   TM   A_i = Gamma_i,    (Gamma_i)(k, j) = Gamma^k_ij:  eq:hor-diff-1
//        d^nabla F = (dF/dx^i - Gamma^k_ij xdot^j dF/dxdot^k) dx^i;
//   T*M  A_i = -Gamma_i^T:                                 eq:hor-diff-2
//        d^nabla F = (dF/dx^i + Gamma^k_ij p_k dF/dp_j) dx^i.
// The paper writes the T*M coefficients as Gamma_ij(x, p) = +Gamma^k_ij p_k; with the minus sign
// of eq:hor-diff-local that would give -Gamma^k_ij p_k in eq:hor-diff-2. The covector transport
// p_j' = +Gamma^k_ij gamma'^i p_k (pairings preserved) needs the minus sign here, and then
// eq:hor-diff-2 holds as printed (docs/paper-notes.md#erratum-8).

#include <array>
#include <functional>
#include <utility>

#include "cartan/errors.hpp"
#include "cartan/manifolds/geometry.hpp"

namespace cartan::manifolds {

template <int BaseDim, int FibreDim>
struct LinearBundle {
  static_assert(BaseDim >= 1 && FibreDim >= 1);
  static constexpr int kBaseDim = BaseDim;
  static constexpr int kFibreDim = FibreDim;
  using BasePoint = Eigen::Matrix<double, BaseDim, 1>;
  using Fibre = Eigen::Matrix<double, FibreDim, 1>;
  using FibreOperator = Eigen::Matrix<double, FibreDim, FibreDim>;
  /// coefficients(x)[i] = A_i(x): Gamma_i^alpha(x, u) = (A_i(x) u)^alpha.
  using Coefficients = std::array<FibreOperator, BaseDim>;
  using CoefficientField = std::function<Coefficients(const BasePoint&)>;

  CoefficientField coefficients;

  /// Throws std::invalid_argument if the field is empty.
  explicit LinearBundle(CoefficientField field) : coefficients(std::move(field)) {
    if (!coefficients) throw_invalid("LinearBundle", "coefficients", "(empty)", "must be a function of the base point");
  }

  /// The matrix of u -> (x'^i A_i(x)) u, the fibre part of the horizontal lift of x' (with a minus).
  FibreOperator along(const BasePoint& x, const BasePoint& velocity) const {
    const Coefficients a = coefficients(x);
    FibreOperator out = FibreOperator::Zero();
    for (int i = 0; i < BaseDim; ++i) out += velocity[i] * a[i];
    return out;
  }
};

/// eq:hor-diff-local at (x, u), from the partial derivatives dF/dx (n) and dF/du (r).
template <int n, int r>
Eigen::Matrix<double, n, 1> horizontal_differential(const LinearBundle<n, r>& bundle, const Eigen::Matrix<double, n, 1>& x,
                                                    const Eigen::Matrix<double, r, 1>& u,
                                                    const Eigen::Matrix<double, n, 1>& dF_dx,
                                                    const Eigen::Matrix<double, r, 1>& dF_du) {
  const auto a = bundle.coefficients(x);
  Eigen::Matrix<double, n, 1> out = dF_dx;
  for (int i = 0; i < n; ++i) out[i] -= (a[i] * u).dot(dF_du);  // Gamma_i^alpha dF/du^alpha
  return out;
}

/// Parallel transport (horizontal lift, eq:hrz-lift-curve) of u0 along the base curve
/// s -> curve(s), s from 0 to s1, with velocity(s) = curve'(s): classical RK4 on
/// u' = -A(curve, velocity) u in `steps` equal steps (error O((s1 / steps)^4)).
template <int n, int r, class Curve, class Velocity>
Eigen::Matrix<double, r, 1> transport_fibre(const LinearBundle<n, r>& bundle, const Curve& curve, const Velocity& velocity,
                                            const Eigen::Matrix<double, r, 1>& u0, double s1, int steps) {
  using Fibre = Eigen::Matrix<double, r, 1>;
  const auto rate = [&](double s, const Fibre& u) -> Fibre {
    return -bundle.along(curve(s), velocity(s)) * u;
  };
  const double h = s1 / steps;
  Fibre u = u0;
  for (int k = 0; k < steps; ++k) {
    const double s = k * h;
    const Fibre k1 = rate(s, u), k2 = rate(s + h / 2, u + h / 2 * k1), k3 = rate(s + h / 2, u + h / 2 * k2),
                k4 = rate(s + h, u + h * k3);
    u += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return u;
}

/// The Christoffel matrices Gamma_i (entry (k, j) = Gamma^k_ij) of a chart at q.
template <ChartWithConnection M>
std::array<OperatorOf<M>, M::kDim> christoffel_matrices(const M& manifold, const PointOf<M>& q) {
  std::array<OperatorOf<M>, M::kDim> out;
  for (int i = 0; i < M::kDim; ++i) out[i] = christoffel_operator(manifold, q, VectorOf<M>(VectorOf<M>::Unit(i)));
  return out;
}

/// TM of a chart as a LinearBundle: A_i = Gamma_i (header comment). Keeps a copy of the manifold.
template <ChartWithConnection M>
LinearBundle<M::kDim, M::kDim> tangent_bundle(const M& manifold) {
  return LinearBundle<M::kDim, M::kDim>([manifold](const PointOf<M>& q) { return christoffel_matrices(manifold, q); });
}

/// T*M of a chart as a LinearBundle: A_i = -Gamma_i^T (header comment; docs/paper-notes.md#erratum-8).
template <ChartWithConnection M>
LinearBundle<M::kDim, M::kDim> cotangent_bundle(const M& manifold) {
  return LinearBundle<M::kDim, M::kDim>([manifold](const PointOf<M>& q) {
    auto a = christoffel_matrices(manifold, q);
    for (auto& m : a) m = OperatorOf<M>(-m.transpose());
    return a;
  });
}

/// eq:hor-diff-1 on TM: dF/dx^i - Gamma^k_ij xdot^j dF/dxdot^k, i.e. dF/dx^i - dF/dxdot . Gamma_q(e_i, xdot).
template <ChartWithConnection M>
VectorOf<M> tangent_horizontal_differential(const M& manifold, const PointOf<M>& q, const VectorOf<M>& xdot,
                                            const VectorOf<M>& dF_dq, const VectorOf<M>& dF_dxdot) {
  VectorOf<M> out = dF_dq;
  for (int i = 0; i < M::kDim; ++i) out[i] -= dF_dxdot.dot(manifold.christoffel(q, VectorOf<M>::Unit(i), xdot));
  return out;
}

/// eq:hor-diff-2 on T*M: dF/dx^i + Gamma^k_ij p_k dF/dp_j, i.e. dF/dx^i + p . Gamma_q(e_i, dF/dp).
template <ChartWithConnection M>
VectorOf<M> cotangent_horizontal_differential(const M& manifold, const PointOf<M>& q, const VectorOf<M>& p,
                                              const VectorOf<M>& dF_dq, const VectorOf<M>& dF_dp) {
  VectorOf<M> out = dF_dq;
  for (int i = 0; i < M::kDim; ++i) out[i] += p.dot(manifold.christoffel(q, VectorOf<M>::Unit(i), dF_dp));
  return out;
}

}  // namespace cartan::manifolds
