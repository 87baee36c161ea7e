#pragma once
// The two-point boundary-value problem of the connection-dependent variational principle on a
// manifold with any linear connection, in the local form of the paper's appendix "Local form of
// the integro-differential Euler–Lagrange equation" (derivation and signs:
// docs/general-connections.md#local-form). In a parallel frame e_i(t) along the curve, with
// e_i(0) = frame0[:, i], gamma' = v^i e_i, mu = dl/dv and Xi^k_n(t) = int_t^T v^k mu_n dr:
//   q'   = e_i v^i,                    q(0) = q0, q(T) = qT
//   e_i' = -Gamma(q', e_i)             (the frame is parallel)
//   mu_i' = delta_{q^i} l + v^j T_ij^k mu_k + v^j R_ijk^n Xi^k_n
//   Xi'  = -v mu^T,                    Xi(T) = 0.

#include <optional>
#include <string>

#include "cartan/errors.hpp"
#include "cartan/manifolds/geometry.hpp"
#include "cartan/mechanics/manifold_lagrangian.hpp"
#include "cartan/numerics/spectrum.hpp"
#include "cartan/principle/horizon.hpp"
#include "cartan/principle/scales.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
struct GeneralProblem {
  M manifold;
  L lagrangian;
  double T = 1.0;
  int N = 100;  ///< steps, h = T / N
  manifolds::PointOf<M> q0;
  manifolds::PointOf<M> qT;
  /// The frame of T_{q0}Q in which v and mu are components; empty: manifolds::default_frame(q0, qT)
  /// (on the quadrics towards qT, elsewhere tangent_basis(q0)).
  std::optional<manifolds::FrameOf<M>> frame0;

  double step() const { return T / N; }
  manifolds::FrameOf<M> initial_frame() const {
    return frame0 ? *frame0 : manifolds::default_frame(manifold, q0, qT);
  }

  /// Throws std::invalid_argument naming the first bad value: T, N, q0, qT, a frame0 that is not
  /// finite, not tangent at q0 or not a basis, or no frame0 where the default one falls back on
  /// tangent_basis(q0) (q0, qT equal, or antipodal on S^2) and the Lagrangian depends on the frame
  /// (mechanics::frame_invariant_of): the problem is then not defined without frame0.
  void validate() const {
    require_horizon(T, N, "GeneralProblem");
    manifold.validate(q0, "q0");
    manifold.validate(qT, "qT");
    if (!frame0) {
      if (!mechanics::frame_invariant_of(lagrangian)) manifolds::require_frame_towards(manifold, q0, qT, "GeneralProblem");
      return;
    }
    require_finite(*frame0, "GeneralProblem", "frame0");
    const manifolds::FrameOf<M> basis = manifold.tangent_basis(q0);
    const manifolds::FrameOf<M> in_span = basis * (manifolds::dual_frame<M>(basis) * *frame0);
    const double size = frame0->cwiseAbs().maxCoeff();
    if (!(size > 0) || (in_span - *frame0).cwiseAbs().maxCoeff() > 1e-9 * size) {
      throw_invalid("GeneralProblem", "frame0", format_value(*frame0), "must consist of tangent vectors at q0");
    }
    if (!(numerics::singular_value_ratio(*frame0) > 1e-10)) {
      throw_invalid("GeneralProblem", "frame0", format_value(*frame0), "must be a basis of the tangent space");
    }
  }
};

/// The geodesic guess: difference(q0, qT) / T in the components of the initial frame.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
manifolds::ComponentsOf<M> geodesic_guess(const GeneralProblem<M, L>& problem) {
  return manifolds::dual_frame<M>(problem.initial_frame()) * problem.manifold.difference(problem.q0, problem.qT) /
         problem.T;
}

/// The unit of Xi on this problem (aux_scale): T |v_ref| |mu_ref|, v_ref the geodesic guess at a
/// speed of at least 1/T (aux_scale_velocity).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
double xi_scale(const GeneralProblem<M, L>& problem) {
  const manifolds::ComponentsOf<M> v = aux_scale_velocity(geodesic_guess(problem), problem.T);
  return aux_scale(problem.T, v.norm(), problem.lagrangian.momentum(0, problem.q0, v).norm());
}

/// Xi's own size on this problem (aux_size): T |v| |mu| at the geodesic guess, or 0.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
double xi_size(const GeneralProblem<M, L>& problem) {
  const manifolds::ComponentsOf<M> v = geodesic_guess(problem);
  return aux_size(problem.T, v.norm(), problem.lagrangian.momentum(0, problem.q0, v).norm());
}

}  // namespace cartan::general
