#pragma once
// Operations derived once for every manifold with a connection (manifold.hpp): the Christoffel
// operator, torsion and curvature from the connection, their components in a frame, covariant
// derivatives of T and R along a direction, and parallel transport along a chain of steps.
// Conventions (docs/general-connections.md#conventions):
//   T(x, y)   = nabla_x y - nabla_y x - [x, y]
//   R(x, y) z = nabla_x nabla_y z - nabla_y nabla_x z - nabla_[x,y] z
// On the representation's constant fields (manifold.hpp), with D Gamma[z] the derivative of
// q -> Gamma_q along z,
//   T(x, y)   = Gamma(x, y) - Gamma(y, x) - [x, y]
//   R(x, y) z = D Gamma[x](y, z) - D Gamma[y](x, z) + Gamma(x, Gamma(y, z)) - Gamma(y, Gamma(x, z))
//               - Gamma([x, y], z).
// Frame components: T(e_i, e_j) = T_ij^k e_k, R(e_i, e_j) e_k = R_ijk^l e_l (paper, appendix
// "Local form of the integro-differential Euler–Lagrange equation").

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>

#include "cartan/errors.hpp"
#include "cartan/manifolds/manifold.hpp"

namespace cartan::manifolds {

/// Instances may provide D Gamma[z](x, y) analytically; otherwise it is a central difference.
template <class M>
concept AnalyticChristoffelDerivative =
    ManifoldWithConnection<M> && requires(const M& manifold, const typename M::Point& q, const typename M::Vector& x) {
      { manifold.christoffel_derivative(q, x, x, x) } -> std::same_as<typename M::Vector>;
    };

/// The matrix of y -> Gamma_q(x, y).
template <ManifoldWithConnection M>
OperatorOf<M> christoffel_operator(const M& manifold, const PointOf<M>& q, const VectorOf<M>& x) {
  OperatorOf<M> out;
  for (int c = 0; c < M::kAmbientDim; ++c) out.col(c) = manifold.christoffel(q, x, VectorOf<M>::Unit(c));
  return out;
}

/// D Gamma[z](x, y): the derivative of q -> Gamma_q(x, y) along z (x, y held as constant fields).
/// Analytic when the instance has it; otherwise the fourth-order central difference along
/// step(q, +-s z), step(q, +-2 s z) with s = eps^(1/5) / max(1, |z|): truncation and rounding
/// errors both ~ eps^(4/5) ~ 3e-13 relative (the second-order difference's eps^(2/3) ~ 4e-11 was
/// the floor of collocation's residual on charts; docs/general-connections.md#collocation).
template <ManifoldWithConnection M>
VectorOf<M> christoffel_derivative(const M& manifold, const PointOf<M>& q, const VectorOf<M>& z, const VectorOf<M>& x,
                                   const VectorOf<M>& y) {
  if constexpr (AnalyticChristoffelDerivative<M>) {
    return manifold.christoffel_derivative(q, z, x, y);
  } else {
    const double s = std::pow(std::numeric_limits<double>::epsilon(), 0.2) / std::max(1.0, z.norm());
    const auto at = [&](double a) { return VectorOf<M>(manifold.christoffel(manifold.step(q, VectorOf<M>(a * z)), x, y)); };
    return (8 * (at(s) - at(-s)) - (at(2 * s) - at(-2 * s))) / (12 * s);
  }
}

/// T(x, y) = Gamma(x, y) - Gamma(y, x) - [x, y].
template <ManifoldWithConnection M>
VectorOf<M> torsion(const M& manifold, const PointOf<M>& q, const VectorOf<M>& x, const VectorOf<M>& y) {
  return manifold.christoffel(q, x, y) - manifold.christoffel(q, y, x) - manifold.frame_bracket(x, y);
}

/// R(x, y) z (header comment).
template <ManifoldWithConnection M>
VectorOf<M> curvature(const M& manifold, const PointOf<M>& q, const VectorOf<M>& x, const VectorOf<M>& y,
                      const VectorOf<M>& z) {
  return christoffel_derivative(manifold, q, x, y, z) - christoffel_derivative(manifold, q, y, x, z) +
         manifold.christoffel(q, x, manifold.christoffel(q, y, z)) -
         manifold.christoffel(q, y, manifold.christoffel(q, x, z)) -
         manifold.christoffel(q, manifold.frame_bracket(x, y), z);
}

/// The matrix of z -> R(x, y) z.
template <ManifoldWithConnection M>
OperatorOf<M> curvature_operator(const M& manifold, const PointOf<M>& q, const VectorOf<M>& x, const VectorOf<M>& y) {
  OperatorOf<M> out;
  for (int c = 0; c < M::kAmbientDim; ++c) out.col(c) = curvature(manifold, q, x, y, VectorOf<M>(VectorOf<M>::Unit(c)));
  return out;
}

/// The dual frame of a frame E of T_qQ: the m x d matrix E^+ with E^+ E = I that maps a tangent
/// vector to its components in E ((E^T E)^{-1} E^T, exact on span E).
template <ManifoldWithConnection M>
Eigen::Matrix<double, M::kDim, M::kAmbientDim> dual_frame(const FrameOf<M>& frame) {
  const ComponentMatrixOf<M> gram = frame.transpose() * frame;
  return gram.ldlt().solve(frame.transpose());
}

/// The default frame of T_{q0}Q of a problem from q0 to qT (docs/general-connections.md#frames):
/// the manifold's frame towards qT where it has one and it is defined there (the quadrics: e1 along
/// the minimal geodesic, so that the frame turns with the endpoints), else tangent_basis(q0).
template <ManifoldWithConnection M>
FrameOf<M> default_frame(const M& manifold, const PointOf<M>& q0, const PointOf<M>& qT) {
  if constexpr (requires { manifold.frame_towards(q0, qT); }) {
    if (const auto frame = manifold.frame_towards(q0, qT)) return *frame;
  }
  return manifold.tangent_basis(q0);
}

/// Throws std::invalid_argument naming q0/qT (as "<where>: q0/qT = ...") where the manifold's frame
/// towards qT is undefined (equal endpoints; antipodal ones on S^2), so that default_frame falls
/// back on the convention tangent_basis(q0): for a Lagrangian that depends on the frame (an
/// anisotropic inertia, a Lagrangian of the user's) the problem is then not defined without frame0.
template <ManifoldWithConnection M>
void require_frame_towards(const M& manifold, const PointOf<M>& q0, const PointOf<M>& qT, std::string_view where) {
  if constexpr (requires { manifold.frame_towards(q0, qT); }) {
    if (!manifold.frame_towards(q0, qT)) {
      throw_invalid(where, "q0/qT", format_value(q0.transpose()) + " / " + format_value(qT.transpose()),
                    std::string((q0 - qT).norm() < 1 ? "are equal" : "are antipodal") +
                        ": the default frame's e1 (towards qT along the minimal geodesic) is undefined, and the "
                        "Lagrangian depends on the frame (an anisotropic inertia or a Lagrangian of its own): give frame0");
    }
  }
}

/// How far b is from a, as the solvers' convergence tests and the verifiers may trust it: the
/// length of difference(a, b) in the components of tangent_basis(a) where that is a logarithm of
/// b, otherwise the storage distance |b - a| (never the zero that a logarithm may return at the
/// cut locus), and +inf when that is not finite. Zero only when b = a.
template <ManifoldWithConnection M>
double separation(const M& manifold, const typename M::Point& a, const typename M::Point& b) {
  const CheckedDifference<M> d = checked_difference(manifold, a, b);
  if (d.reaches) {
    return (dual_frame<M>(manifold.tangent_basis(a)) * d.x).norm();
  }
  const double gap = point_distance(manifold, a, b);
  return std::isfinite(gap) ? gap : std::numeric_limits<double>::infinity();
}

/// Frame components T_ij^k (entry [i](k, j), i.e. the m x m matrix of e_j -> T(e_i, e_j) in the frame).
template <ManifoldWithConnection M>
std::array<ComponentMatrixOf<M>, M::kDim> torsion_components(const M& manifold, const PointOf<M>& q,
                                                            const FrameOf<M>& frame) {
  const auto dual = dual_frame<M>(frame);
  std::array<ComponentMatrixOf<M>, M::kDim> out;
  for (int i = 0; i < M::kDim; ++i) {
    for (int j = 0; j < M::kDim; ++j) {
      out[i].col(j) = dual * torsion(manifold, q, VectorOf<M>(frame.col(i)), VectorOf<M>(frame.col(j)));
    }
  }
  return out;
}

/// Frame components R_ijk^l (entry [i][j](l, k): the m x m matrix of e_k -> R(e_i, e_j) e_k in the frame).
template <ManifoldWithConnection M>
std::array<std::array<ComponentMatrixOf<M>, M::kDim>, M::kDim> curvature_components(const M& manifold,
                                                                                 const PointOf<M>& q,
                                                                                 const FrameOf<M>& frame) {
  const auto dual = dual_frame<M>(frame);
  std::array<std::array<ComponentMatrixOf<M>, M::kDim>, M::kDim> out;
  for (int i = 0; i < M::kDim; ++i) {
    for (int j = 0; j < M::kDim; ++j) {
      out[i][j] = dual * curvature_operator(manifold, q, VectorOf<M>(frame.col(i)), VectorOf<M>(frame.col(j))) * frame;
    }
  }
  return out;
}

/// Parallel transport of the frame `frame` at q along step(q, s x), s in [0, 1].
template <ManifoldWithConnection M>
FrameOf<M> transport_frame(const M& manifold, const PointOf<M>& q, const VectorOf<M>& x, const FrameOf<M>& frame) {
  return manifold.transport_along_step(q, x) * frame;
}

/// (nabla_w T)(x, y) at q, from its characterisation by parallel frames: the derivative at s = 0 of
/// P_s^{-1} T_{c(s)}(P_s x, P_s y), with c(s) = step(q, s w) and P_s the transport along c.
/// Central difference with s = eps^(1/3) / max(1, |w|); x, y tangent at q.
template <ManifoldWithConnection M>
VectorOf<M> covariant_derivative_torsion(const M& manifold, const PointOf<M>& q, const VectorOf<M>& w,
                                         const VectorOf<M>& x, const VectorOf<M>& y) {
  const double s = std::cbrt(std::numeric_limits<double>::epsilon()) / std::max(1.0, w.norm());
  auto pulled_back = [&](double sign) {
    const VectorOf<M> dw = sign * s * w;
    const OperatorOf<M> p = manifold.transport_along_step(q, dw);
    const VectorOf<M> value = torsion(manifold, manifold.step(q, dw), VectorOf<M>(p * x), VectorOf<M>(p * y));
    return VectorOf<M>(p.colPivHouseholderQr().solve(value));
  };
  return (pulled_back(1) - pulled_back(-1)) / (2 * s);
}

/// (nabla_w R)(x, y) z at q, as covariant_derivative_torsion.
template <ManifoldWithConnection M>
VectorOf<M> covariant_derivative_curvature(const M& manifold, const PointOf<M>& q, const VectorOf<M>& w,
                                           const VectorOf<M>& x, const VectorOf<M>& y, const VectorOf<M>& z) {
  const double s = std::cbrt(std::numeric_limits<double>::epsilon()) / std::max(1.0, w.norm());
  auto pulled_back = [&](double sign) {
    const VectorOf<M> dw = sign * s * w;
    const OperatorOf<M> p = manifold.transport_along_step(q, dw);
    const VectorOf<M> value =
        curvature(manifold, manifold.step(q, dw), VectorOf<M>(p * x), VectorOf<M>(p * y), VectorOf<M>(p * z));
    return VectorOf<M>(p.colPivHouseholderQr().solve(value));
  };
  return (pulled_back(1) - pulled_back(-1)) / (2 * s);
}

}  // namespace cartan::manifolds
