#pragma once
// Left- and right-invariant affine connections on a Lie group, given by a bilinear map on the
// algebra (paper §3 "Invariant connections on Lie groups" and appendix "Right formalism").
//
// A left-invariant connection is fixed by its left bilinear map
//   nabla^L_v w := (nabla_{v^L} w^L)_e                                   (paper, §3)
// and acts on arbitrary fields by (eq:left-conn)
//   (nabla_V W)_g = g [ V_g(g^{-1} W) + nabla^L_{g^{-1} V_g} (g^{-1} W_g) ].
// A right-invariant connection is the same with right trivialisation (X g^{-1}).
// We store the map by its coefficient matrices Gamma_i (n x n): nabla_u w = sum_i u_i Gamma_i w,
// i.e. Gamma_i is the matrix of w -> nabla_{E_i} w.

#include <array>
#include <random>
#include <string>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/groups/side.hpp"

namespace cartan::connections {

template <groups::LieGroup G>
class InvariantConnection {
 public:
  static constexpr int kDim = G::kDim;
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;
  using Operator = groups::AlgebraMatrixOf<G>;
  using Coefficients = std::array<Operator, kDim>;

  /// From coefficient matrices: coefficients[i] is the matrix of w -> nabla_{E_i} w.
  InvariantConnection(groups::Side side, const Coefficients& coefficients) : side_(side), gamma_(coefficients) {
    for (int i = 0; i < kDim; ++i) {
      require_finite(gamma_[i], "InvariantConnection", "coefficients[" + std::to_string(i) + "]");
    }
  }

  /// From a table of structure coefficients: an n x n^2 matrix whose column i*n + j holds
  /// nabla_{E_i} E_j. Throws std::invalid_argument on a wrong shape or a non-finite entry.
  static InvariantConnection from_table(groups::Side side, const Eigen::MatrixXd& table) {
    require_shape(table, kDim, kDim * kDim, "InvariantConnection::from_table", "table");
    require_finite(table, "InvariantConnection::from_table", "table");
    Coefficients c;
    for (int i = 0; i < kDim; ++i) c[i] = table.block(0, i * kDim, kDim, kDim);
    return InvariantConnection(side, c);
  }

  /// From any bilinear map f(u, w) -> g, sampled on the basis. The map is then checked for
  /// bilinearity at seeded random points (relative 1e-10); a non-bilinear f is rejected.
  template <class F>
  static InvariantConnection from_bilinear(groups::Side side, const F& f) {
    Coefficients c;
    for (int i = 0; i < kDim; ++i) {
      for (int j = 0; j < kDim; ++j) c[i].col(j) = f(Tangent(Tangent::Unit(i)), Tangent(Tangent::Unit(j)));
    }
    InvariantConnection conn(side, c);
    std::mt19937 rng(7u);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int trial = 0; trial < 3; ++trial) {
      Tangent u, w;
      for (int k = 0; k < kDim; ++k) {
        u[k] = uniform(rng);
        w[k] = uniform(rng);
      }
      const Tangent direct = f(u, w);
      const Tangent sampled = conn.nabla(u, w);
      if ((direct - sampled).norm() > 1e-10 * (1 + direct.norm())) {
        throw_invalid("InvariantConnection::from_bilinear", "f(u, w)", format_value(direct),
                      "differs from its bilinear extension " + format_value(sampled) + " at u = " +
                          format_value(u) + ", w = " + format_value(w) + ": the map is not bilinear");
      }
    }
    return conn;
  }

  groups::Side side() const { return side_; }
  const Coefficients& coefficients() const { return gamma_; }

  /// nabla_u w (the left or right bilinear map).
  Tangent nabla(const Tangent& u, const Tangent& w) const { return nabla_operator(u) * w; }

  /// Matrix of w -> nabla_u w.
  Operator nabla_operator(const Tangent& u) const {
    Operator m = Operator::Zero();
    for (int i = 0; i < kDim; ++i) m += u[i] * gamma_[i];
    return m;
  }

  /// Matrix of u -> nabla_u w (the paper's "nabla^L w" in the proof of thm-EP).
  Operator nabla_operator_first(const Tangent& w) const {
    Operator m;
    for (int i = 0; i < kDim; ++i) m.col(i) = gamma_[i] * w;
    return m;
  }

  /// nabla*_u alpha, the adjoint on g*: <nabla*_u alpha, w> = <alpha, nabla_u w>.
  Covector nabla_dual(const Tangent& u, const Covector& alpha) const {
    return nabla_operator(u).transpose() * alpha;
  }

  /// Torsion on invariant fields (cur-tor-left; right version from the appendix):
  ///   left:  T(v,w) = nabla_v w - nabla_w v - [v,w];  right: ... + [v,w].
  Tangent torsion(const Tangent& v, const Tangent& w) const {
    return nabla(v, w) - nabla(w, v) - sign() * groups::bracket<G>(v, w);
  }

  /// The covector w -> alpha . T(v, w) (the torsion term alpha(i_v T) of eq:EL-1 and eq:HE-1).
  Covector torsion_dual(const Tangent& v, const Covector& alpha) const {
    Covector out;
    for (int i = 0; i < kDim; ++i) out[i] = alpha.dot(torsion(v, Tangent::Unit(i)));
    return out;
  }

  /// Curvature on invariant fields (cur-tor-left; right version from the appendix):
  ///   left:  R(u,v)w = nabla_u nabla_v w - nabla_v nabla_u w - nabla_[u,v] w;  right: ... + nabla_[u,v] w.
  Tangent curvature(const Tangent& u, const Tangent& v, const Tangent& w) const {
    return nabla(u, nabla(v, w)) - nabla(v, nabla(u, w)) - sign() * nabla(groups::bracket<G>(u, v), w);
  }

  /// Covariant derivative in trivialised form (eq:cov-curve-left, eq:left-conn):
  /// for a curve (or a field V) with trivialised velocity u, a trivialised field W and its
  /// derivative dW along the curve, D/dt W = translate( dW + nabla_u W ).
  Tangent covariant_derivative(const Tangent& u, const Tangent& w, const Tangent& dw) const {
    return dw + nabla(u, w);
  }

  /// Dual covariant derivative (eq:cov-curve-left-dual): D/dt alpha = d alpha/dt - nabla*_u alpha.
  Covector covariant_derivative_dual(const Tangent& u, const Covector& alpha, const Covector& dalpha) const {
    return dalpha - nabla_dual(u, alpha);
  }

  /// Generator of parallel transport in trivialised form (cor-parr): the transported vector
  /// Y(t) = Texp(-int nabla_{u(r)} dr) Y(s) solves Y' = A(u) Y with A(u) = -nabla_u.
  Operator transport_generator(const Tangent& u) const { return -nabla_operator(u); }

  /// A Cartan connection has a skew-symmetric bilinear map (geodesics through e are
  /// one-parameter subgroups).
  bool is_cartan(double tolerance = 1e-14) const {
    for (int i = 0; i < kDim; ++i) {
      for (int j = 0; j < kDim; ++j) {
        if ((gamma_[i].col(j) + gamma_[j].col(i)).cwiseAbs().maxCoeff() > tolerance) return false;
      }
    }
    return true;
  }

 private:
  double sign() const { return side_ == groups::Side::Left ? 1.0 : -1.0; }

  groups::Side side_;
  Coefficients gamma_;
};

}  // namespace cartan::connections
