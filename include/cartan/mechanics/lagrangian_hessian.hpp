#pragma once
// Second derivatives of a reduced Lagrangian, needed by tangent-linear (forward-sensitivity)
// sweeps. A model may provide them analytically as `hessian(t, g, v)` returning
// LagrangianHessian<G>; otherwise they are computed by central differences of its first
// derivatives (momentum, group_gradient).

#include "cartan/mechanics/lagrangian.hpp"

namespace cartan::mechanics {

/// Derivatives of mu = dl/dv and zeta = trivialised dl/dg, with g perturbed as g exp(e gamma)
/// (left-trivialised gamma) and v as v + e dv.
template <groups::LieGroup G>
struct LagrangianHessian {
  groups::AlgebraMatrixOf<G> momentum_v;  ///< d mu / dv   (d^2 l / dv^2)
  groups::AlgebraMatrixOf<G> momentum_g;  ///< d mu / d gamma
  groups::AlgebraMatrixOf<G> gradient_v;  ///< d zeta / dv
  groups::AlgebraMatrixOf<G> gradient_g;  ///< d zeta / d gamma
};

/// All four blocks finite (for require_finite_result).
template <groups::LieGroup G>
bool all_finite(const LagrangianHessian<G>& h) {
  return h.momentum_v.allFinite() && h.momentum_g.allFinite() && h.gradient_v.allFinite() && h.gradient_g.allFinite();
}

/// What a model may declare about its second derivatives, as static constexpr bool members
/// (absent: no structure), so that tangent-linear sweeps skip the zero blocks and invert a
/// constant d^2 l/dv^2 once instead of at every step:
///   kConstantMomentumHessian             mu = M v with a constant M: d mu/dv = M, d mu/d gamma = 0
///   kGroupGradientIndependentOfVelocity  d zeta/dv = 0
///   kZeroGroupGradient                   zeta = 0 everywhere (so d zeta = 0)
/// A declaration is a promise: the tangent-linear tests compare the sweeps that use it with
/// differences of the scheme (tests/transported/test_scheme.cpp).
template <class L>
struct HessianStructure {
  static constexpr bool constant_momentum_hessian = requires { requires L::kConstantMomentumHessian; };
  static constexpr bool gradient_independent_of_velocity =
      requires { requires L::kGroupGradientIndependentOfVelocity; };
  static constexpr bool zero_group_gradient = requires { requires L::kZeroGroupGradient; };
};

/// Central-difference step: truncation ~ step^2 |l'''|, rounding ~ 1e-16 / step: both ~1e-10.
inline constexpr double kHessianStep = 1e-5;

/// Second derivatives by central differences of momentum and group_gradient.
template <groups::LieGroup G, ReducedLagrangian<G> L>
LagrangianHessian<G> lagrangian_hessian_fd(const L& l, double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
    LagrangianHessian<G> out;
    const double hv = kHessianStep * (1 + v.cwiseAbs().maxCoeff());
    const double hg = kHessianStep;
    for (int i = 0; i < G::kDim; ++i) {
      const groups::TangentOf<G> ev = groups::TangentOf<G>::Unit(i) * hv;
      const groups::TangentOf<G> vp = v + ev, vm = v - ev;
      out.momentum_v.col(i) = (groups::CovectorOf<G>(l.momentum(t, g, vp)) - groups::CovectorOf<G>(l.momentum(t, g, vm))) / (2 * hv);
      out.gradient_v.col(i) =
          (groups::CovectorOf<G>(l.group_gradient(t, g, vp)) - groups::CovectorOf<G>(l.group_gradient(t, g, vm))) / (2 * hv);
      const groups::TangentOf<G> eg = groups::TangentOf<G>::Unit(i) * hg;
      const groups::ElementOf<G> gp = G::compose(g, G::exp(eg));
      const groups::ElementOf<G> gm = G::compose(g, G::exp(groups::TangentOf<G>(-eg)));
      out.momentum_g.col(i) = (groups::CovectorOf<G>(l.momentum(t, gp, v)) - groups::CovectorOf<G>(l.momentum(t, gm, v))) / (2 * hg);
      out.gradient_g.col(i) =
          (groups::CovectorOf<G>(l.group_gradient(t, gp, v)) - groups::CovectorOf<G>(l.group_gradient(t, gm, v))) / (2 * hg);
    }
    return out;
}

/// The model's analytic `hessian(t, g, v)` when it has one (checked: require_finite_result),
/// central differences otherwise.
template <groups::LieGroup G, ReducedLagrangian<G> L>
LagrangianHessian<G> lagrangian_hessian(const L& l, double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
  if constexpr (requires { { l.hessian(t, g, v) } -> std::convertible_to<LagrangianHessian<G>>; }) {
    return require_finite_result(LagrangianHessian<G>(l.hessian(t, g, v)), "lagrangian.hessian", t, g, v);
  } else {
    return lagrangian_hessian_fd<G>(l, t, g, v);
  }
}

}  // namespace cartan::mechanics
