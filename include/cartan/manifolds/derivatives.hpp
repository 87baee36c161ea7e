#pragma once
// First derivatives of an instance's pieces (manifold.hpp), for the tangent-linear sweep of the
// general scheme (kernels/manifold/tangent.hpp). Points are perturbed along pieces, q_e = step(q, e dq)
// with dq a represented tangent vector at q, so a point's variation is a `Vector` tangent at it.
// An instance may give each derivative in closed form; otherwise it is a central difference of
// the instance's own functions (step eps^(1/3): error ~ eps^(2/3) ~ 4e-11 relative), which is
// consistent with the primal scheme because it differentiates the very functions the scheme calls.
//   step_jacobians(q, x)            d step(q, x) = point dq + vector dx, read at step(q, x) through
//                                   difference (the local inverse of step there)
//   transport_along_step_derivative(q, x, dx)   d/de transport_along_step(q, x + e dx)
//   kPointIndependentConnection     christoffel and transport_along_step do not depend on the point
//                                   in this representation (constant coefficients; left-invariant
//                                   connections in the left trivialisation)

#include <array>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/MatrixFunctions>

#include "cartan/manifolds/geometry.hpp"

namespace cartan::manifolds {

/// Unconstrained, so that an instance can name it in its own members.
template <class M>
struct StepJacobians {
  typename M::Operator point;   ///< on dq, tangent at q
  typename M::Operator vector;  ///< on dx
};

template <class M>
concept PointIndependentConnection = ManifoldWithConnection<M> && requires {
  requires M::kPointIndependentConnection;
};

/// The central-difference step for a direction of unit size at a point of size `scale`.
inline double central_difference_step(double scale = 1.0) {
  return std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, scale);
}

/// d/de exp(A + e dA) at e = 0. For |A|_inf <= 1/2 (the scheme's steps), the series
/// sum_k S_k / k! with S_1 = dA, S_{k+1} = A S_k + dA A^k, stopped when a term is below eps of the
/// sum (|S_k| / k! <= |A|^(k-1) / (k-1)! |dA|: at most 18 terms); otherwise the upper right block
/// of exp([[A, dA], [0, A]]) (exact to rounding, six times the work at n = 3).
template <int n>
Eigen::Matrix<double, n, n> exp_derivative(const Eigen::Matrix<double, n, n>& a, const Eigen::Matrix<double, n, n>& da) {
  using Matrix = Eigen::Matrix<double, n, n>;
  if (a.cwiseAbs().rowwise().sum().maxCoeff() <= 0.5) {
    Matrix s = da, power = a, sum = da;
    double factorial = 1;
    for (int k = 2; k <= 40; ++k) {
      s = Matrix(a * s) + Matrix(da * power);
      power = Matrix(power * a);
      factorial *= k;
      const Matrix term = s / factorial;
      sum += term;
      if (term.cwiseAbs().maxCoeff() <= std::numeric_limits<double>::epsilon() * sum.cwiseAbs().maxCoeff()) break;
    }
    return sum;
  }
  Eigen::Matrix<double, 2 * n, 2 * n> block = Eigen::Matrix<double, 2 * n, 2 * n>::Zero();
  block.template topLeftCorner<n, n>() = a;
  block.template bottomRightCorner<n, n>() = a;
  block.template topRightCorner<n, n>() = da;
  return Eigen::Matrix<double, 2 * n, 2 * n>(block.exp()).template topRightCorner<n, n>();
}

/// The d x d matrix taking a tangent vector at q to its components in tangent_basis(q), padded
/// to act on represented vectors: B B^+ acts as the identity on tangent vectors.
template <ManifoldWithConnection M>
Eigen::Matrix<double, M::kDim, M::kAmbientDim> tangent_coordinates(const M& manifold, const PointOf<M>& q) {
  return dual_frame<M>(manifold.tangent_basis(q));
}

/// The derivatives of f(q) (values in R^r) along tangent vectors at q, as an r x d matrix acting
/// on represented tangent vectors: central differences along tangent_basis(q).
template <ManifoldWithConnection M, class F>
auto point_derivative(const M& manifold, const PointOf<M>& q, const F& f) {
  using Value = decltype(f(q));
  constexpr int m = M::kDim;
  const FrameOf<M> basis = manifold.tangent_basis(q);
  const double s = central_difference_step();
  Eigen::Matrix<double, Value::RowsAtCompileTime, m> along;
  for (int j = 0; j < m; ++j) {
    const VectorOf<M> e = s * basis.col(j);
    along.col(j) = (f(manifold.step(q, e)) - f(manifold.step(q, VectorOf<M>(-e)))) / (2 * s);
  }
  return Eigen::Matrix<double, Value::RowsAtCompileTime, M::kAmbientDim>(along * dual_frame<M>(basis));
}

/// The derivatives of difference(a, b) along b (header comment): d x d on tangent vectors at b.
template <ManifoldWithConnection M>
OperatorOf<M> difference_derivative(const M& manifold, const PointOf<M>& a, const PointOf<M>& b) {
  return point_derivative(manifold, b, [&](const PointOf<M>& p) { return manifold.difference(a, p); });
}

/// The instance's step_jacobians(q, x) if it has them, otherwise central differences.
template <ManifoldWithConnection M>
StepJacobians<M> step_jacobians(const M& manifold, const PointOf<M>& q, const VectorOf<M>& x) {
  if constexpr (requires { { manifold.step_jacobians(q, x) } -> std::same_as<StepJacobians<M>>; }) {
    return manifold.step_jacobians(q, x);
  } else {
    const PointOf<M> end = manifold.step(q, x);
    StepJacobians<M> out;
    out.point = point_derivative(manifold, q, [&](const PointOf<M>& p) { return manifold.difference(end, manifold.step(p, x)); });
    const double s = central_difference_step(x.norm());
    for (int a = 0; a < M::kAmbientDim; ++a) {
      const VectorOf<M> e = s * VectorOf<M>::Unit(a);
      out.vector.col(a) = (manifold.difference(end, manifold.step(q, VectorOf<M>(x + e))) -
                           manifold.difference(end, manifold.step(q, VectorOf<M>(x - e)))) / (2 * s);
    }
    return out;
  }
}

/// The derivatives of transport_along_step(q, x) at (q, x).
template <ManifoldWithConnection M>
struct TransportJacobians {
  OperatorOf<M> value;                                    ///< transport_along_step(q, x)
  std::array<OperatorOf<M>, M::kAmbientDim> vector;       ///< along x's unit vectors
  std::array<OperatorOf<M>, M::kDim> point;               ///< along tangent_basis(q)'s columns
  Eigen::Matrix<double, M::kDim, M::kAmbientDim> coordinates;  ///< tangent_coordinates(q)
  bool point_independent = false;                         ///< then `point` is zero and unused

  /// d transport for a point variation dq (tangent) and a vector variation dx.
  OperatorOf<M> derivative(const VectorOf<M>& dq, const VectorOf<M>& dx) const {
    OperatorOf<M> out = OperatorOf<M>::Zero();
    for (int a = 0; a < M::kAmbientDim; ++a) out += dx[a] * vector[a];
    if (!point_independent) {
      const ComponentsOf<M> c = coordinates * dq;
      for (int j = 0; j < M::kDim; ++j) out += c[j] * point[j];
    }
    return out;
  }
};

template <ManifoldWithConnection M>
TransportJacobians<M> transport_jacobians(const M& manifold, const PointOf<M>& q, const VectorOf<M>& x) {
  TransportJacobians<M> out;
  out.value = manifold.transport_along_step(q, x);
  const double s = central_difference_step(x.norm());
  for (int a = 0; a < M::kAmbientDim; ++a) {
    const VectorOf<M> e = VectorOf<M>::Unit(a);
    if constexpr (requires { { manifold.transport_along_step_derivative(q, x, e) } -> std::same_as<OperatorOf<M>>; }) {
      out.vector[a] = manifold.transport_along_step_derivative(q, x, e);
    } else {
      out.vector[a] = (manifold.transport_along_step(q, VectorOf<M>(x + s * e)) -
                       manifold.transport_along_step(q, VectorOf<M>(x - s * e))) / (2 * s);
    }
  }
  out.point_independent = PointIndependentConnection<M>;
  if constexpr (!PointIndependentConnection<M>) {
    const FrameOf<M> basis = manifold.tangent_basis(q);
    out.coordinates = dual_frame<M>(basis);
    const double t = central_difference_step();
    for (int j = 0; j < M::kDim; ++j) {
      const VectorOf<M> e = t * basis.col(j);
      out.point[j] = (manifold.transport_along_step(manifold.step(q, e), x) -
                      manifold.transport_along_step(manifold.step(q, VectorOf<M>(-e)), x)) / (2 * t);
    }
  }
  return out;
}

}  // namespace cartan::manifolds
