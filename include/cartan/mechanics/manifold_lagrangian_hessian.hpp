#pragma once
// Second derivatives (LagrangianHessian, manifold_lagrangian.hpp) of a Lagrangian of the general problem,
// for the tangent-linear sweep (kernels/manifold/tangent.hpp); the counterpart of lagrangian_hessian.hpp, with
// the point perturbed along pieces, q_e = step(q, e dq) (manifolds/derivatives.hpp). A Lagrangian
// may provide them as `hessian(manifold, t, q, v)`; otherwise they are central differences of
// momentum and point_gradient.

#include "cartan/mechanics/manifold_lagrangian.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
LagrangianHessian<M> lagrangian_hessian_fd(const M& manifold, const L& l, double t, const manifolds::PointOf<M>& q,
                                           const manifolds::ComponentsOf<M>& v) {
  using Components = manifolds::ComponentsOf<M>;
  using Vector = manifolds::VectorOf<M>;
  LagrangianHessian<M> out;
  const double hv = mechanics::kHessianStep * (1 + v.cwiseAbs().maxCoeff());
  for (int i = 0; i < M::kDim; ++i) {
    const Components e = Components::Unit(i) * hv;
    const Components vp = v + e, vm = v - e;
    out.momentum_v.col(i) = (Components(l.momentum(t, q, vp)) - Components(l.momentum(t, q, vm))) / (2 * hv);
    out.gradient_v.col(i) = (Vector(l.point_gradient(t, q, vp)) - Vector(l.point_gradient(t, q, vm))) / (2 * hv);
  }
  out.momentum_q = manifolds::point_derivative(manifold, q, [&](const manifolds::PointOf<M>& p) {
    return Components(l.momentum(t, p, v));
  });
  out.gradient_q = manifolds::point_derivative(manifold, q, [&](const manifolds::PointOf<M>& p) {
    return Vector(l.point_gradient(t, p, v));
  });
  return out;
}

/// The Lagrangian's `hessian(manifold, t, q, v)` when it has one, central differences otherwise;
/// throws ModelError (naming the callback) if an entry is not finite although q and v are finite
/// and moderate (mechanics::require_finite_result's rule): at a diverging iterate's point the
/// non-finite Hessian is returned, and the sweep that needs it fails as the solver's business.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
LagrangianHessian<M> lagrangian_hessian(const M& manifold, const L& l, double t, const manifolds::PointOf<M>& q,
                                        const manifolds::ComponentsOf<M>& v) {
  LagrangianHessian<M> h;
  if constexpr (requires { { l.hessian(manifold, t, q, v) } -> std::convertible_to<LagrangianHessian<M>>; }) {
    h = l.hessian(manifold, t, q, v);
  } else {
    h = lagrangian_hessian_fd(manifold, l, t, q, v);
  }
  if (!h.all_finite() && mechanics::moderate_arguments(t, q, v)) {
    throw ModelError("lagrangian.hessian returned a non-finite value at t = " + format_value(t) + ", v = " +
                     format_value(v));
  }
  return h;
}

}  // namespace cartan::general
