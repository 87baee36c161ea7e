#pragma once
// The concept of a manifold with a linear connection that the general transported-velocity
// solver is written against (paper §"Connection-dependent variational principles"), in the style
// of the Lie group concept (groups/group.hpp). Derivation and conventions: docs/general-connections.md.
//
// Representation. An instance represents points by a `Point` (chart coordinates, a point of an
// embedding, a group element) and tangent vectors at q by a `Vector` in R^d, d = kAmbientDim >= m =
// kDim: chart components (d = m), ambient components of an embedding (d > m), or components in a
// global frame such as the left trivialisation of a Lie group (d = m). A `Vector` x also stands for
// the "constant field" with components x near q; two such fields have the bracket
// `frame_bracket(x, y)` (0 for charts and embeddings, [x, y] for left-invariant fields).
//
// Connection. For a curve q(t) with represented velocity u and a vector field Y(t) along it with
// components y(t),
//   (nabla_{q'} Y)(t) = y'(t) + christoffel(q, u, y),
// so `christoffel(q, x, y)` is Gamma_q(x, y) = Gamma^a_bc x^b y^c in a chart, alpha(x, y) for a
// left-invariant connection with bilinear map alpha, and q (x . y) for the sphere in R^3.
// Torsion T(x, y) = Gamma(x, y) - Gamma(y, x) - [x, y] and the curvature follow (geometry.hpp).
//
// Curves. `step(q, x)` is the point reached at s = 1 along the instance's "straight" curve
// c(s) = step(q, s x) (the chart line q + s x, g exp(s x), a great circle), `difference(a, b)` its
// local inverse (step(a, difference(a, b)) = b), and `transport_along_step(q, x)` the d x d matrix
// of parallel transport along c from c(0) to c(1), exact or accurate to rounding. The discrete
// curves of the solver are chains of such pieces.

#include <Eigen/Dense>
#include <cmath>
#include <concepts>
#include <limits>
#include <optional>
#include <string_view>

namespace cartan::manifolds {

template <class M>
concept ManifoldWithConnection =
    requires(const M& manifold, const typename M::Point& q, const typename M::Vector& x, std::string_view where) {
      requires M::kDim >= 1 && M::kAmbientDim >= M::kDim;
      requires std::same_as<typename M::Vector, Eigen::Matrix<double, M::kAmbientDim, 1>>;
      requires std::same_as<typename M::Frame, Eigen::Matrix<double, M::kAmbientDim, M::kDim>>;
      requires std::same_as<typename M::Operator, Eigen::Matrix<double, M::kAmbientDim, M::kAmbientDim>>;
      { manifold.name() } -> std::convertible_to<std::string_view>;
      { manifold.christoffel(q, x, x) } -> std::same_as<typename M::Vector>;
      { manifold.frame_bracket(x, x) } -> std::same_as<typename M::Vector>;
      { manifold.step(q, x) } -> std::same_as<typename M::Point>;
      { manifold.difference(q, q) } -> std::same_as<typename M::Vector>;
      { manifold.transport_along_step(q, x) } -> std::same_as<typename M::Operator>;
      // A basis of T_qQ (orthonormal where the instance has a metric), d x m.
      { manifold.tangent_basis(q) } -> std::same_as<typename M::Frame>;
      // Throws std::invalid_argument naming `where` unless q is a valid point.
      { manifold.validate(q, where) } -> std::same_as<void>;
    };

/// Instances that may have a metric g_q(x, y) = x^T metric(q) y preserved by the connection:
/// `metric(q)` returns the matrix (or an empty optional when this instance has none).
template <class M>
concept MetricManifold = ManifoldWithConnection<M> && requires(const M& manifold, const typename M::Point& q) {
  { manifold.metric(q) } -> std::convertible_to<std::optional<typename M::Operator>>;
};

/// Instances whose torsion and curvature are parallel (nabla T = nabla R = 0), so that their
/// components in a parallel frame are constant along every curve: the solver's fast path.
template <class M>
concept ParallelTorsionCurvature = ManifoldWithConnection<M> && requires(const M& manifold) {
  { manifold.has_parallel_torsion_and_curvature() } -> std::same_as<bool>;
};

/// Instances whose points and vectors are the coordinates of one chart (Euclidean<m>, Chart<m>):
/// Point = Vector = R^m, constant fields are the coordinate fields (frame_bracket = 0) and
/// `christoffel` gives the coordinate Christoffel symbols Gamma^k_ij x^i y^j. Coordinate-wise
/// integrators (kernels/manifold/hamilton.hpp) and the bundles of manifolds/bundle.hpp need no more.
template <class M>
concept ChartWithConnection =
    ManifoldWithConnection<M> && M::kAmbientDim == M::kDim && std::same_as<typename M::Point, typename M::Vector>;

/// The metric at q as an optional (empty where the instance has none or is not a MetricManifold).
template <class M>
std::optional<typename M::Operator> metric_at(const M& manifold, const typename M::Point& q) {
  if constexpr (MetricManifold<M>) {
    return std::optional<typename M::Operator>(manifold.metric(q));
  } else {
    return std::nullopt;
  }
}

/// d/ds of the point's storage along a curve with represented velocity x at q: x itself where
/// points and vectors share their coordinates (charts, embeddings), otherwise the instance's
/// `point_velocity(q, x)` (d(L_g)_e x for a group element). Used by collocation, which integrates
/// the stored point.
template <ManifoldWithConnection M>
typename M::Point point_velocity(const M& manifold, const typename M::Point& q, const typename M::Vector& x) {
  if constexpr (requires { { manifold.point_velocity(q, x) } -> std::convertible_to<typename M::Point>; }) {
    return manifold.point_velocity(q, x);
  } else {
    static_assert(std::same_as<typename M::Point, typename M::Vector>,
                  "an instance whose points are not vectors must define point_velocity(q, x)");
    return x;
  }
}

/// The distance of two points in their storage, |b - a|: the embedding's (chordal) distance on
/// the quadrics, the distance of the matrices of group elements, of coordinates in a chart; or
/// the instance's own `point_distance(a, b)`. Zero exactly when the points are equal; NaN when
/// either is not finite. Used where the logarithm cannot be trusted (separation).
template <ManifoldWithConnection M>
double point_distance(const M& manifold, const typename M::Point& a, const typename M::Point& b) {
  if constexpr (requires { { manifold.point_distance(a, b) } -> std::convertible_to<double>; }) {
    return manifold.point_distance(a, b);
  } else {
    return (b - a).norm();
  }
}

/// Where difference(a, b) is a logarithm, i.e. step(a, difference(a, b)) returns to b: to within
/// kLogRoundTrip (1 + |b|) in storage. Away from the cut locus the round trip is exact to
/// rounding (~1e-15); at it (antipodal points of a sphere, a rotation by pi outside the principal
/// logarithm) or outside a chart's domain it misses b by O(1) or gives NaN. 1e-8 = sqrt(eps)
/// leaves room for logarithms that lose half their digits near the cut locus.
inline constexpr double kLogRoundTrip = 1e-8;

/// The difference x = difference(a, b) with its verdict: `reaches` is false where x is not a
/// logarithm of b at a (the round trip above fails, or x is not finite).
template <ManifoldWithConnection M>
struct CheckedDifference {
  typename M::Vector x;
  bool reaches = false;
};

template <ManifoldWithConnection M>
CheckedDifference<M> checked_difference(const M& manifold, const typename M::Point& a, const typename M::Point& b) {
  CheckedDifference<M> out{manifold.difference(a, b), false};
  if (!out.x.allFinite()) return out;
  double size = 0;  // |b| in storage, where the storage has a norm
  if constexpr (requires { { b.norm() } -> std::convertible_to<double>; }) size = b.norm();
  out.reaches = point_distance(manifold, manifold.step(a, out.x), b) <= kLogRoundTrip * (1 + size);
  return out;
}

template <ManifoldWithConnection M> using PointOf = typename M::Point;
template <ManifoldWithConnection M> using VectorOf = typename M::Vector;
template <ManifoldWithConnection M> using FrameOf = typename M::Frame;
template <ManifoldWithConnection M> using OperatorOf = typename M::Operator;
/// Components in a frame of T_{q0}Q (the transported velocity v, the momentum mu).
template <ManifoldWithConnection M> using ComponentsOf = Eigen::Matrix<double, M::kDim, 1>;
/// m x m matrices on frame components (the auxiliary Xi, frame-component operators).
template <ManifoldWithConnection M> using ComponentMatrixOf = Eigen::Matrix<double, M::kDim, M::kDim>;

}  // namespace cartan::manifolds
