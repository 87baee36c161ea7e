#pragma once
// Second derivatives of a reduced Lagrangian, needed by tangent-linear (forward-sensitivity)
// sweeps. A model may provide them analytically as `hessian(t, g, v)` returning
// LagrangianHessian<G>; otherwise they are computed by central differences of its first
// derivatives (momentum, group_gradient).

#include <concepts>
#include <array>

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
/// differences of the scheme (tests/kernels/lie_group/test_scheme.cpp).
template <class L>
struct HessianStructure {
  static constexpr bool constant_momentum_hessian = requires { requires L::kConstantMomentumHessian; };
  static constexpr bool gradient_independent_of_velocity =
      requires { requires L::kGroupGradientIndependentOfVelocity; };
  static constexpr bool zero_group_gradient = requires { requires L::kZeroGroupGradient; };
};

/// A Hessian structure known at run time: what a Lagrangian behind an erased type declares
/// (HessianStructure of the wrapped type, or what it reports), so that the schemes skip the same
/// work for it (kernels/lie_group/scheme.hpp).
struct RuntimeHessianStructure {
  bool constant_momentum_hessian = false;
  bool gradient_independent_of_velocity = false;
  bool zero_group_gradient = false;
};

/// The structure of `lagrangian`: what it reports (`hessian_structure()`: an erased Lagrangian, a
/// KineticPotential, an adapter), else what its type declares (HessianStructure).
template <class L>
RuntimeHessianStructure hessian_structure_of(const L& lagrangian) {
  if constexpr (requires {
                  { lagrangian.hessian_structure() } -> std::convertible_to<RuntimeHessianStructure>;
                }) {
    return lagrangian.hessian_structure();
  } else {
    return {HessianStructure<L>::constant_momentum_hessian, HessianStructure<L>::gradient_independent_of_velocity,
            HessianStructure<L>::zero_group_gradient};
  }
}

/// Central-difference step: truncation ~ step^2 |l'''|, rounding ~ 1e-16 / step: both ~1e-10.
inline constexpr double kHessianStep = 1e-5;

/// The 4 dim points at which lagrangian_hessian_fd evaluates momentum and group_gradient, in
/// the order point(i, j): for direction i, j = 0, 1 move v by +-hv e_i, j = 2, 3 move g to
/// g exp(+-hg e_i). A model that evaluates many points in one call (a vectorised Python
/// Lagrangian) takes them all at once and hands the values to hessian_from_stencil.
template <groups::LieGroup G>
struct HessianStencil {
  static constexpr int kPoints = 4 * G::kDim;
  double hv = 0, hg = 0;
  std::array<groups::ElementOf<G>, kPoints> g;
  std::array<groups::TangentOf<G>, kPoints> v;
  static constexpr int index(int direction, int j) { return 4 * direction + j; }
};

template <groups::LieGroup G>
HessianStencil<G> hessian_stencil(const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
  HessianStencil<G> s;
  s.hv = kHessianStep * (1 + v.cwiseAbs().maxCoeff());
  s.hg = kHessianStep;
  for (int i = 0; i < G::kDim; ++i) {
    const groups::TangentOf<G> ev = groups::TangentOf<G>::Unit(i) * s.hv;
    const groups::TangentOf<G> eg = groups::TangentOf<G>::Unit(i) * s.hg;
    const int k = HessianStencil<G>::index(i, 0);
    s.g[k] = g, s.v[k] = v + ev;
    s.g[k + 1] = g, s.v[k + 1] = v - ev;
    s.g[k + 2] = G::compose(g, G::exp(eg)), s.v[k + 2] = v;
    s.g[k + 3] = G::compose(g, G::exp(groups::TangentOf<G>(-eg))), s.v[k + 3] = v;
  }
  return s;
}

/// The central differences of momentum (mu[k]) and group_gradient (zeta[k]) at the stencil's points.
template <groups::LieGroup G>
LagrangianHessian<G> hessian_from_stencil(const HessianStencil<G>& s, const std::array<groups::CovectorOf<G>, HessianStencil<G>::kPoints>& mu,
                                          const std::array<groups::CovectorOf<G>, HessianStencil<G>::kPoints>& zeta) {
  LagrangianHessian<G> out;
  for (int i = 0; i < G::kDim; ++i) {
    const int k = HessianStencil<G>::index(i, 0);
    out.momentum_v.col(i) = (mu[k] - mu[k + 1]) / (2 * s.hv);
    out.gradient_v.col(i) = (zeta[k] - zeta[k + 1]) / (2 * s.hv);
    out.momentum_g.col(i) = (mu[k + 2] - mu[k + 3]) / (2 * s.hg);
    out.gradient_g.col(i) = (zeta[k + 2] - zeta[k + 3]) / (2 * s.hg);
  }
  return out;
}

/// Second derivatives by central differences of momentum and group_gradient.
template <groups::LieGroup G, ReducedLagrangian<G> L>
LagrangianHessian<G> lagrangian_hessian_fd(const L& l, double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
  const HessianStencil<G> s = hessian_stencil<G>(g, v);
  std::array<groups::CovectorOf<G>, HessianStencil<G>::kPoints> mu, zeta;
  for (int k = 0; k < HessianStencil<G>::kPoints; ++k) {
    mu[k] = l.momentum(t, s.g[k], s.v[k]);
    zeta[k] = l.group_gradient(t, s.g[k], s.v[k]);
  }
  return hessian_from_stencil<G>(s, mu, zeta);
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
