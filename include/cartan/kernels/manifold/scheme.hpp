#pragma once
// The discrete scheme of the general transported-velocity problem (principle/manifold_problem.hpp),
// order 1 and 2.
// State at node k: q_k, the parallel frame E_k (d x m, columns e_i(t_k)), mu_k, Xi_k, v_k.
// Rates (manifold_problem.hpp, docs/general-connections.md#scheme), with u = E v the represented velocity:
//   zeta_i = point_gradient . e_i
//   mu'_i  = zeta_i + mu(T(e_i, u)) + tr(Xi E^+ R(e_i, u) E)       (E^+ the dual frame)
//   Xi'    = -v mu^T
// Order 1: explicit Euler in (mu, Xi) and the exact piece for (q, E):
//   q_{k+1} = step(q_k, h u_k),  E_{k+1} = transport_along_step(q_k, h u_k) E_k.
// Order 2: Heun's method in Runge–Kutta–Munthe-Kaas form (as kernels/lie_group/scheme.hpp): a predictor
// Euler step, then the same update with the mean of the rates at the node and the predictor.
// On a Lie group with the Cartan–Schouten connection these are exactly the paper's equations
// (disc-grp ... disc-mmt-eqn) with E_k = P_k = Ad(h_k) and xi = C(Xi) (docs/general-connections.md#reduction).
// Fast path: where nabla T = nabla R = 0, the frame components T_ij^k, R_ijk^l are the same at
// every node and are computed once at (q0, E0).

#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include "cartan/kernels/manifold/solution.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/principle/manifold_problem.hpp"
#include "cartan/principle/samples.hpp"

namespace cartan::general {

using ::cartan::SchemeOrder;  // scheme_order.hpp: the vocabulary of both stacks

/// Throws std::invalid_argument naming `what` (the one check of samples, principle/samples.hpp)
/// unless x has at least 2 times from 0 to the problem's T (strictly increasing), as many q,
/// frame, v, mu and Xi as times, all finite.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
void validate_trajectory(const GeneralProblem<M, L>& problem, const GeneralTrajectory<M>& x, std::string_view where,
                         std::string_view what) {
  require_samples(x.t, problem.T,
                  {sample_column("q", x.q), sample_column("frame", x.frame), sample_column("v", x.v),
                   sample_column("mu", x.mu), sample_column("Xi", x.Xi)},
                  SampleRules{}, where, what);
}

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
class GeneralScheme {
 public:
  static constexpr int m = M::kDim;
  using Node = GeneralNode<M>;
  using Point = manifolds::PointOf<M>;
  using Vector = manifolds::VectorOf<M>;
  using Frame = manifolds::FrameOf<M>;
  using Components = manifolds::ComponentsOf<M>;
  using ComponentMatrix = manifolds::ComponentMatrixOf<M>;

  /// Throws std::invalid_argument for an invalid problem or order.
  GeneralScheme(const GeneralProblem<M, L>& problem, SchemeOrder order)
      : problem_(problem), order_(order), dt_(problem.step()), frame0_(problem.initial_frame()) {
    problem.validate();
    require_scheme_order(order, "GeneralScheme");
    if constexpr (manifolds::ParallelTorsionCurvature<M>) {
      if (problem.manifold.has_parallel_torsion_and_curvature()) {
        torsion_ = manifolds::torsion_components(problem.manifold, problem.q0, frame0_);
        curvature_ = manifolds::curvature_components(problem.manifold, problem.q0, frame0_);
      }
    }
  }

  const GeneralProblem<M, L>& problem() const { return problem_; }
  SchemeOrder order() const { return order_; }
  bool uses_constant_components() const { return torsion_.has_value(); }

  Components velocity(double t, const Point& q, const Components& mu) const {
    return mechanics::require_finite_result(Components(problem_.lagrangian.velocity(t, q, mu)), "lagrangian.velocity",
                                            t, point_coordinates(q), mu);
  }

  Node initial(const Components& v0, const ComponentMatrix& Xi0) const {
    Node node;
    node.q = problem_.q0;
    node.frame = frame0_;
    node.v = v0;
    node.mu = mechanics::require_finite_result(Components(problem_.lagrangian.momentum(0.0, node.q, v0)),
                                               "lagrangian.momentum", 0.0, point_coordinates(node.q), v0);
    node.Xi = Xi0;
    return node;
  }

  /// The rates at a node: u = E v, the point gradient zeta, mu' and Xi' (header comment).
  struct Rates {
    Vector u;
    Vector gradient;
    Components dmu;
    ComponentMatrix dXi;
  };

  void step(const Node& node, Node& out) const {
    const Rates r1 = rates(node);
    if (order_ == SchemeOrder::First) return advance(node, r1, out);
    Node predictor;
    advance(node, r1, predictor);
    advance(node, mean(r1, rates(predictor)), out);
  }

  static Rates mean(const Rates& a, const Rates& b) {
    return {Vector((a.u + b.u) / 2), Vector((a.gradient + b.gradient) / 2), Components((a.dmu + b.dmu) / 2),
            ComponentMatrix((a.dXi + b.dXi) / 2)};
  }

  /// The terminal residual in the components of tangent_basis(qT): difference(qT, q_N).
  Components terminal_residual(const Node& last) const { return terminal_residual(last.q); }
  Components terminal_residual(const Point& q) const {
    const Frame basis = problem_.manifold.tangent_basis(problem_.qT);
    return manifolds::dual_frame<M>(basis) * problem_.manifold.difference(problem_.qT, q);
  }
  /// False where difference(qT, q) is not a logarithm (q at the cut locus of qT, or NaN): there
  /// the terminal residual means nothing and must not be read as small (manifolds/manifold.hpp).
  bool terminal_residual_defined(const Point& q) const {
    return manifolds::checked_difference(problem_.manifold, problem_.qT, q).reaches;
  }
  /// The terminal error a convergence test may trust: separation(qT, q) (manifolds/geometry.hpp).
  double terminal_error(const Point& q) const { return manifolds::separation(problem_.manifold, problem_.qT, q); }

  /// The rate of mu at a node (mu' of manifold_problem.hpp), for the checks of the equations.
  Components momentum_rate(const Node& node) const { return rates(node).dmu; }

  /// The frame components T_ij^k and R_ijk^l when they are constant (the fast path), else null.
  const std::array<ComponentMatrix, m>* constant_torsion() const { return torsion_ ? &*torsion_ : nullptr; }
  const std::array<std::array<ComponentMatrix, m>, m>* constant_curvature() const {
    return curvature_ ? &*curvature_ : nullptr;
  }

  Rates rates(const Node& node) const {
    Rates r;
    r.u = node.frame * node.v;
    r.gradient = mechanics::require_finite_result(Vector(problem_.lagrangian.point_gradient(node.t, node.q, node.v)),
                                                  "lagrangian.point_gradient", node.t, point_coordinates(node.q), node.v);
    r.dmu = node.frame.transpose() * r.gradient;
    if (torsion_) {
      for (int i = 0; i < m; ++i) {
        double curvature_term = 0;
        for (int j = 0; j < m; ++j) curvature_term += node.v[j] * ((*curvature_)[i][j] * node.Xi).trace();
        r.dmu[i] += node.mu.dot((*torsion_)[i] * node.v) + curvature_term;
      }
    } else {
      r.dmu += connection_rate(node.q, node.frame, node.v, node.mu, node.Xi);
    }
    r.dXi = -node.v * node.mu.transpose();
    return r;
  }

  /// The torsion and curvature terms of mu' computed at q (the general path):
  /// mu(T(e_i, u)) + tr(Xi E^+ R(e_i, u) E), u = E v, in the ambient form of the header comment.
  Components connection_rate(const Point& q, const Frame& frame, const Components& v, const Components& mu,
                             const ComponentMatrix& Xi) const {
    const M& manifold = problem_.manifold;
    const Vector u = frame * v;
    const auto dual = manifolds::dual_frame<M>(frame);
    const Vector mu_ambient = dual.transpose() * mu;
    const Eigen::Matrix<double, M::kAmbientDim, M::kAmbientDim> xi_ambient = frame * Xi * dual;
    Components out;
    for (int i = 0; i < m; ++i) {
      const Vector e = frame.col(i);
      out[i] = mu_ambient.dot(manifolds::torsion(manifold, q, e, u)) +
               (xi_ambient * manifolds::curvature_operator(manifold, q, e, u)).trace();
    }
    return out;
  }

  /// The node reached from `node` with the rates r (order 1: r at the node; order 2: their mean).
  void advance(const Node& node, const Rates& r, Node& out) const {
    const Vector hu = dt_ * r.u;
    out.t = next_node_time(node.t, dt_, problem_.T);
    out.q = problem_.manifold.step(node.q, hu);
    out.frame = problem_.manifold.transport_along_step(node.q, hu) * node.frame;
    out.mu = node.mu + dt_ * r.dmu;
    out.Xi = node.Xi + dt_ * r.dXi;
    out.v = velocity(out.t, out.q, out.mu);
  }

  double step_size() const { return dt_; }

 private:
  template <class P>
  static auto point_coordinates(const P& q) {
    return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 1>>(q.data(), q.size());
  }

  GeneralProblem<M, L> problem_;
  SchemeOrder order_;
  double dt_;
  Frame frame0_;
  std::optional<std::array<ComponentMatrix, m>> torsion_;
  std::optional<std::array<std::array<ComponentMatrix, m>, m>> curvature_;
};

}  // namespace cartan::general
