#pragma once
// The tangent-linear sweep of the general scheme (scheme.hpp): the derivatives of every node with
// respect to the shooting unknowns (v0, Xi0), carried forward with the primal nodes, so that one
// sweep gives the terminal residual and its Jacobian (docs/general-connections.md#tangent-linear).
// The counterpart of kernels/lie_group/scheme.hpp's advance_tangent; here the n = m + m^2 directions
// are the columns of fixed-size matrices.
//
// Variations: dq is a represented tangent vector at q (points perturbed along pieces,
// manifolds/derivatives.hpp); dE, dmu, dXi, dv are variations of the stored values. Per step:
//   du   = dE v + E dv
//   dmu' = dE^T zeta + E^T (zeta_q dq + zeta_v dv) + d(connection terms)
//   dXi' = -(dv mu^T + v dmu^T)
//   dq+  = S_q dq + S_x h du,   dE+ = P dE + (dP[dq, h du]) E       (step_jacobians, transport_jacobians)
//   dmu+ = dmu + h dmu',  dXi+ = dXi + h dXi',  dv+ = mu_v^{-1} (dmu+ - mu_q dq+)  (LagrangianHessian)
// The connection terms: on the fast path T_ij^k, R_ijk^l are constants and the terms are
// multilinear in (v, mu, Xi). Otherwise, with Phi(x, y) = mu_amb . T(x, y) + tr(xi_amb R(x, y)),
// mu_amb = E^{+T} mu and xi_amb = E Xi E^+, the terms are E^T Phi u, whose variation is
//   dE^T Phi u + E^T Phi du + [dmu_amb . T(e_i, u) + tr(dxi_amb R(e_i, u))]_i + (D_q terms) dq
// with dE^+ = -E^+ dE E^+ + (E^T E)^{-1} dE^T (I - E E^+); D_q is a central difference unless the
// connection does not depend on the point (then T and R at the ambient basis are computed once).

#include <array>
#include <optional>

#include "cartan/kernels/manifold/scheme.hpp"
#include "cartan/manifolds/derivatives.hpp"
#include "cartan/mechanics/manifold_lagrangian_hessian.hpp"

namespace cartan::general {

/// The variations of a node along the n = m + m^2 shooting directions: column j < m is d/d v0_j,
/// column m + k is d/d (Xi0 reshaped)_k (column-major).
template <manifolds::ManifoldWithConnection M>
struct GeneralNodeTangent {
  static constexpr int m = M::kDim, d = M::kAmbientDim, n = m + m * m;
  Eigen::Matrix<double, d, n> q;
  Eigen::Matrix<double, d * m, n> frame;  ///< dE, column-major
  Eigen::Matrix<double, m, n> mu, v;
  Eigen::Matrix<double, m * m, n> Xi;     ///< dXi, column-major
  LagrangianHessian<M> hessian;           ///< at the node
};

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
class GeneralSchemeTangent {
 public:
  static constexpr int m = M::kDim, d = M::kAmbientDim, n = m + m * m;
  using Scheme = GeneralScheme<M, L>;
  using Node = GeneralNode<M>;
  using Tangent = GeneralNodeTangent<M>;
  using Rates = typename Scheme::Rates;
  using Vector = manifolds::VectorOf<M>;
  using Frame = manifolds::FrameOf<M>;
  using Operator = manifolds::OperatorOf<M>;
  using Components = manifolds::ComponentsOf<M>;
  using ComponentMatrix = manifolds::ComponentMatrixOf<M>;

  /// Keeps a reference to `scheme`, which must outlive it.
  explicit GeneralSchemeTangent(const Scheme& scheme) : scheme_(scheme) {
    if constexpr (manifolds::PointIndependentConnection<M>) {
      if (!scheme.constant_torsion()) ambient_ = ambient_tensors(scheme.problem().q0);
    }
  }

  /// The variations of the initial node: dv0 = identity on the first m columns, dXi0 on the rest.
  Tangent initial(const Node& node) const {
    Tangent t;
    t.q.setZero();
    t.frame.setZero();
    t.v.setZero();
    t.v.template leftCols<m>().setIdentity();
    t.Xi.setZero();
    t.Xi.template rightCols<m * m>().setIdentity();
    t.hessian = hessian_at(node);
    t.mu = t.hessian.momentum_v * t.v;
    return t;
  }

  /// One step of the scheme and of its variations (the same arithmetic as Scheme::step for `out`).
  void step(const Node& node, const Tangent& dn, Node& out, Tangent& dout) const {
    const Rates r1 = scheme_.rates(node);
    const Variations dr1 = rates_tangent(node, r1, dn);
    if (scheme_.order() == SchemeOrder::First) {
      scheme_.advance(node, r1, out);
      return advance_tangent(node, r1, dn, dr1, out, dout);
    }
    Node predictor;
    Tangent dpredictor;
    scheme_.advance(node, r1, predictor);
    advance_tangent(node, r1, dn, dr1, predictor, dpredictor);
    const Rates r2 = scheme_.rates(predictor);
    const Variations dr2 = rates_tangent(predictor, r2, dpredictor);
    const Rates r = Scheme::mean(r1, r2);
    scheme_.advance(node, r, out);
    advance_tangent(node, r, dn, Variations{(dr1.u + dr2.u) / 2, (dr1.dmu + dr2.dmu) / 2, (dr1.dXi + dr2.dXi) / 2},
                    out, dout);
  }

  /// d terminal_residual / d (v0, Xi0) from the last node's variations (an m x n block).
  Eigen::Matrix<double, m, n> terminal_residual_tangent(const Node& last, const Tangent& dlast) const {
    const auto& problem = scheme_.problem();
    const auto dual = manifolds::dual_frame<M>(problem.manifold.tangent_basis(problem.qT));
    return dual * manifolds::difference_derivative(problem.manifold, problem.qT, last.q) * dlast.q;
  }

 private:
  struct Variations {
    Eigen::Matrix<double, d, n> u;
    Eigen::Matrix<double, m, n> dmu;
    Eigen::Matrix<double, m * m, n> dXi;
  };
  /// T and R on the ambient basis: torsion[a].col(b) = T(e_a, e_b), curvature[a][b] = R(e_a, e_b).
  struct AmbientTensors {
    std::array<Operator, d> torsion;
    std::array<std::array<Operator, d>, d> curvature;

    Vector torsion_of(const Vector& x, const Vector& y) const {
      Vector out = Vector::Zero();
      for (int a = 0; a < d; ++a) out += x[a] * (torsion[a] * y);
      return out;
    }
    Operator curvature_of(const Vector& x, const Vector& y) const {
      Operator out = Operator::Zero();
      for (int a = 0; a < d; ++a) {
        for (int b = 0; b < d; ++b) out += x[a] * y[b] * curvature[a][b];
      }
      return out;
    }
  };

  static Eigen::Map<const Frame> frame_column(const Eigen::Matrix<double, d * m, n>& df, int c) {
    return Eigen::Map<const Frame>(df.col(c).data());
  }

  AmbientTensors ambient_tensors(const manifolds::PointOf<M>& q) const {
    const M& manifold = scheme_.problem().manifold;
    AmbientTensors t;
    for (int a = 0; a < d; ++a) {
      for (int b = 0; b < d; ++b) {
        const Vector ea = Vector::Unit(a), eb = Vector::Unit(b);
        t.torsion[a].col(b) = manifolds::torsion(manifold, q, ea, eb);
        t.curvature[a][b] = manifolds::curvature_operator(manifold, q, ea, eb);
      }
    }
    return t;
  }

  LagrangianHessian<M> hessian_at(const Node& node) const {
    return lagrangian_hessian(scheme_.problem().manifold, scheme_.problem().lagrangian, node.t, node.q, node.v);
  }

  Variations rates_tangent(const Node& node, const Rates& r, const Tangent& dn) const {
    Variations out;
    for (int c = 0; c < n; ++c) out.u.col(c) = frame_column(dn.frame, c) * node.v + node.frame * dn.v.col(c);
    const Eigen::Matrix<double, d, n> dgradient = dn.hessian.gradient_q * dn.q + dn.hessian.gradient_v * dn.v;
    out.dmu = node.frame.transpose() * dgradient;
    for (int c = 0; c < n; ++c) out.dmu.col(c) += frame_column(dn.frame, c).transpose() * r.gradient;
    if (const auto* torsion = scheme_.constant_torsion()) {
      const auto& curvature = *scheme_.constant_curvature();
      for (int c = 0; c < n; ++c) {
        const Eigen::Map<const ComponentMatrix> dXi(dn.Xi.col(c).data());
        for (int i = 0; i < m; ++i) {
          double term = dn.mu.col(c).dot((*torsion)[i] * node.v) + node.mu.dot((*torsion)[i] * dn.v.col(c));
          for (int j = 0; j < m; ++j) {
            term += dn.v(j, c) * (curvature[i][j] * node.Xi).trace() + node.v[j] * (curvature[i][j] * dXi).trace();
          }
          out.dmu(i, c) += term;
        }
      }
    } else {
      add_connection_rate_tangent(node, r, dn, out);
    }
    for (int c = 0; c < n; ++c) {
      out.dXi.col(c) = (-(dn.v.col(c) * node.mu.transpose() + node.v * dn.mu.col(c).transpose())).reshaped();
    }
    return out;
  }

  /// The variation of the general path's connection terms (header comment).
  void add_connection_rate_tangent(const Node& node, const Rates& r, const Tangent& dn, Variations& out) const {
    using Ambient = Eigen::Matrix<double, d, d>;
    const AmbientTensors t = ambient_ ? *ambient_ : ambient_tensors(node.q);
    const Frame& E = node.frame;
    const ComponentMatrix gram = E.transpose() * E;
    const Eigen::Matrix<double, m, d> dual = gram.ldlt().solve(E.transpose());
    const Ambient normal = Ambient::Identity() - E * dual;
    const Vector mu_ambient = dual.transpose() * node.mu;
    const Ambient xi_ambient = E * node.Xi * dual;
    Ambient phi;
    for (int a = 0; a < d; ++a) {
      for (int b = 0; b < d; ++b) {
        phi(a, b) = mu_ambient.dot(t.torsion[a].col(b)) + (xi_ambient * t.curvature[a][b]).trace();
      }
    }
    const Vector phi_u = phi * r.u;
    const Eigen::Matrix<double, m, d> et_phi = E.transpose() * phi;
    Eigen::Matrix<double, m, d> torsion_rows;  // row i: T(e_i, u)^T
    std::array<Ambient, m> curvature_at;       // R(e_i, u)
    for (int i = 0; i < m; ++i) {
      torsion_rows.row(i) = t.torsion_of(E.col(i), r.u).transpose();
      curvature_at[i] = t.curvature_of(E.col(i), r.u);
    }
    Eigen::Matrix<double, m, d> point_derivative = Eigen::Matrix<double, m, d>::Zero();
    if constexpr (!manifolds::PointIndependentConnection<M>) {
      point_derivative = manifolds::point_derivative(scheme_.problem().manifold, node.q, [&](const manifolds::PointOf<M>& p) {
        return scheme_.connection_rate(p, E, node.v, node.mu, node.Xi);
      });
    }
    for (int c = 0; c < n; ++c) {
      const auto dE = frame_column(dn.frame, c);
      const Eigen::Map<const ComponentMatrix> dXi(dn.Xi.col(c).data());
      const Eigen::Matrix<double, m, d> ddual =
          -dual * dE * dual + gram.ldlt().solve(Eigen::Matrix<double, m, d>(dE.transpose() * normal));
      const Vector dmu_ambient = dual.transpose() * dn.mu.col(c) + ddual.transpose() * node.mu;
      const Ambient dxi_ambient = dE * node.Xi * dual + E * dXi * dual + E * node.Xi * ddual;
      Components term = dE.transpose() * phi_u + et_phi * out.u.col(c) + torsion_rows * dmu_ambient +
                        point_derivative * dn.q.col(c);
      for (int i = 0; i < m; ++i) term[i] += (dxi_ambient * curvature_at[i]).trace();
      out.dmu.col(c) += term;
    }
  }

  void advance_tangent(const Node& node, const Rates& r, const Tangent& dn, const Variations& dr, const Node& out,
                       Tangent& dout) const {
    const M& manifold = scheme_.problem().manifold;
    const double h = scheme_.step_size();
    const Vector x = h * r.u;
    const Eigen::Matrix<double, d, n> dx = h * dr.u;
    const manifolds::StepJacobians<M> sj = manifolds::step_jacobians(manifold, node.q, x);
    dout.q = sj.point * dn.q + sj.vector * dx;
    const manifolds::TransportJacobians<M> tj = manifolds::transport_jacobians(manifold, node.q, x);
    for (int c = 0; c < n; ++c) {
      const Frame dE = tj.value * frame_column(dn.frame, c) + tj.derivative(dn.q.col(c), dx.col(c)) * node.frame;
      dout.frame.col(c) = dE.reshaped();
    }
    dout.mu = dn.mu + h * dr.dmu;
    dout.Xi = dn.Xi + h * dr.dXi;
    dout.hessian = hessian_at(out);
    dout.v = dout.hessian.momentum_v.lu().solve(Eigen::Matrix<double, m, n>(dout.mu - dout.hessian.momentum_q * dout.q));
  }

  const Scheme& scheme_;
  std::optional<AmbientTensors> ambient_;
};

}  // namespace cartan::general
