#pragma once
// The discrete transported-velocity scheme: one step k -> k+1 of the paper's discretisation
// (disc-grp, disc-body-v, disc-exp, disc-Legendre, disc-aux, disc-mmt, disc-mmt-eqn) and of a
// second-order variant, together with its tangent-linear (forward-sensitivity) map. Every
// solver (two-level, shooting, multiple shooting, continuation) calls this and nothing else.
//
// State at node k: g_k, the transport element h_k, mu_k, xi_k, v_k = (dl/dv)^{-1}(mu_k).
// The transport operator of the paper is P_k = Ad(h_k): since exp(ad_X) = Ad_{exp X},
// (disc-exp) P_{k+1} = exp(-lambda h ad_{u_k}) P_k is exactly h_{k+1} = exp(-lambda h u_k) h_k.
// Rates at a node (eq:reduced-system; v is left-trivialised at g0 and eta = P^T zeta:
// docs/paper-notes.md#convention-trivialisation, docs/paper-notes.md#convention-dual-transport):
//   u   = P v                                          (disc-body-v)
//   mu' = P^T zeta - (2 lambda - 1) ad*_v mu - lambda (1 - lambda) ad*_v xi   (disc-mmt, disc-mmt-eqn)
//   xi' = -ad*_v mu                                     (disc-aux)
// Order 1 (the paper): explicit Euler in these rates with the Lie–Euler group updates
//   g_{k+1} = g_k exp(h u_k) (disc-grp), h_{k+1} = exp(-lambda h u_k) h_k (disc-exp).
// Order 2 (ours, docs/paper-notes.md#erratum-3): Heun's method in Runge–Kutta–Munthe-Kaas form: a
// predictor Euler step, then the same update with the average of the rates at the node and at
// the predictor; the transport update becomes exp(-lambda (h/2)(u_k + u*)), i.e. Magnus-2 with
// the trapezoidal Omega_1.
// Two modes for xi: `augmented` integrates xi forward from a given xi_0; `given` takes the
// sequence {xi_k} from outside (the paper's outer fixed point) and records the rates for the
// backward recursion xi_k = xi_{k+1} - h xi'_k (disc-aux). The order-2 predictor always takes
// xi* = xi_k + h xi'_k, in both modes, so that a fixed point of the given mode is exactly a
// solution of the augmented mode (the same discrete equations).

#include <optional>
#include <vector>

#include "cartan/groups/exp_jacobian.hpp"
#include "cartan/kernels/lie_group/trajectory.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"
#include "cartan/principle/group_problem.hpp"
#include "cartan/scheme_order.hpp"

namespace cartan::transported {

using ::cartan::SchemeOrder;  // scheme_order.hpp: the vocabulary of both stacks

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class TransportedScheme {
 public:
  static constexpr int n = G::kDim;
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;
  using Matrix = groups::AlgebraMatrixOf<G>;
  using Node = SchemeNode<G>;
  /// Perturbation directions, one column per unknown: at most 4n (a node's whole state, for
  /// multiple shooting), a bound that keeps every tangent-linear temporary off the heap.
  static constexpr int kMaxColumns = 4 * n;
  using Directions = Eigen::Matrix<double, n, Eigen::Dynamic, Eigen::ColMajor, n, kMaxColumns>;
  /// The model's declared Hessian structure (mechanics/lagrangian_hessian.hpp).
  using Structure = mechanics::HessianStructure<L>;

  /// Linearisation of a node: gamma (left-trivialised dg), chi (dh = chi h), dmu, dxi, dv.
  struct NodeTangent {
    Directions gamma, chi, mu, xi, v;
    mechanics::LagrangianHessian<G> hessian;
  };

  /// Throws std::invalid_argument for an invalid problem (TransportedProblem::validate) or order.
  TransportedScheme(const TransportedProblem<G, L>& problem, SchemeOrder order)
      : problem_(problem), order_(order), dt_(problem.step()), c_torsion_(2 * problem.lambda - 1),
        c_curvature_(problem.lambda * (1 - problem.lambda)),
        structure_(mechanics::hessian_structure_of(problem.lagrangian)) {
    problem.validate();
    require_scheme_order(order, "TransportedScheme");
    if (structure_.constant_momentum_hessian) {
      constant_hessian_ = mechanics::lagrangian_hessian<G>(problem.lagrangian, 0.0, problem.g0, Tangent::Zero());
      momentum_v_inverse_ = constant_hessian_.momentum_v.inverse();
    }
  }

  const TransportedProblem<G, L>& problem() const { return problem_; }
  SchemeOrder order() const { return order_; }
  double step_size() const { return dt_; }

  /// The Lagrangian's inverse Legendre map v(t, g, mu), checked (require_finite_result).
  Tangent velocity(double t, const groups::ElementOf<G>& g, const Covector& mu) const {
    return mechanics::require_finite_result(Tangent(problem_.lagrangian.velocity(t, g, mu)), "lagrangian.velocity", t,
                                            g, mu);
  }

  Node initial(const Tangent& v0, const Covector& xi0) const {
    Node node;
    node.t = 0;
    node.g = problem_.g0;
    node.transport = G::identity();
    node.v = v0;
    node.mu = mechanics::require_finite_result(Covector(problem_.lagrangian.momentum(0.0, node.g, v0)),
                                               "lagrangian.momentum", 0.0, node.g, v0);
    node.xi = xi0;
    return node;
  }

  /// Tangent of the initial node along `columns` directions: the first n columns perturb v0,
  /// the next n (if present) perturb xi0.
  NodeTangent initial_tangent(const Node& node, int columns) const {
    if (columns < 1 || columns > kMaxColumns) {
      throw_invalid("TransportedScheme::initial_tangent", "columns", std::to_string(columns),
                    "must be between 1 and " + std::to_string(kMaxColumns));
    }
    NodeTangent d;
    for (Directions* m : {&d.gamma, &d.chi, &d.mu, &d.xi, &d.v}) m->setZero(n, columns);
    d.v.leftCols(n).setIdentity();
    if (columns >= 2 * n) d.xi.middleCols(n, n).setIdentity();
    d.hessian = node_hessian(node.t, node.g, node.v);
    d.mu = d.hessian.momentum_v * d.v;
    return d;
  }

  /// Whether xi never feeds back into g, the transport, mu and v: the curvature term
  /// lambda (1 - lambda) ad*_v xi vanishes (lambda = 0 or 1, exactly). Then a node's derivative
  /// along xi0 is exactly dxi = I and zero elsewhere, and need not be propagated.
  bool xi_decoupled() const { return c_curvature_ == 0; }

  /// Appends the n columns of the directions along xi0 to a tangent propagated along v0 alone
  /// (n columns) in the augmented mode when xi_decoupled(): zero, and dxi = I.
  static void append_decoupled_xi_columns(NodeTangent& d) {
    for (Directions* m : {&d.gamma, &d.chi, &d.mu, &d.v}) {
      m->conservativeResize(n, 2 * n);
      m->rightCols(n).setZero();
    }
    d.xi.conservativeResize(n, 2 * n);
    d.xi.rightCols(n).setIdentity();
  }

  /// Tangent of an arbitrary node along its own state, 4n columns: gamma, chi, mu, xi in turn
  /// (identity blocks), and v = (dl/dv)^{-1}(mu) follows: dv = M_v^{-1} (dmu - M_g gamma).
  /// Multiple shooting starts its segments with it.
  NodeTangent state_tangent(const Node& node) const {
    NodeTangent d;
    for (Directions* m : {&d.gamma, &d.chi, &d.mu, &d.xi}) m->setZero(n, 4 * n);
    d.gamma.leftCols(n).setIdentity();
    d.chi.middleCols(n, n).setIdentity();
    d.mu.middleCols(2 * n, n).setIdentity();
    d.xi.rightCols(n).setIdentity();
    d.hessian = node_hessian(node.t, node.g, node.v);
    d.v = velocity_tangent(d.hessian, d.mu, d.gamma);
    return d;
  }

  /// One step from `node` (at t_k). In `given` mode (xi_next set) the node's xi is the given
  /// xi_k and the result gets xi_{k+1} = *xi_next. Returns the effective xi rate used, so that
  /// xi_{k+1} = xi_k + h * rate.
  Covector step(const Node& node, Node& out, const Covector* xi_next = nullptr) const {
    const NodeRates r1 = rates(node);
    if (order_ == SchemeOrder::First) {
      advance(node, r1, step_elements(r1.u), out, xi_next);
      return r1.dxi;
    }
    Node predictor;
    advance(node, r1, step_elements(r1.u), predictor, nullptr);
    const Rates r2 = rates(predictor);
    const Rates mean = average(r1, r2);
    advance(node, mean, step_elements(mean.u), out, xi_next);
    return mean.dxi;
  }

  /// The step together with its tangent-linear map (d -> dout); returns the xi rate as `step`.
  Covector step_tangent(const Node& node, const NodeTangent& d, Node& out, NodeTangent& dout,
                        const Covector* xi_next = nullptr) const {
    const NodeRates r1 = rates(node);
    const RatesTangent dr1 = rates_tangent(node, d, r1);
    if (order_ == SchemeOrder::First) {
      const StepLinearisation step = step_linearisation(r1.u);
      advance(node, r1, step.elements, out, xi_next);
      advance_tangent(d, dr1, step, out, dout, xi_next != nullptr);
      return r1.dxi;
    }
    Node predictor;
    NodeTangent dpredictor;
    const StepLinearisation first = step_linearisation(r1.u);
    advance(node, r1, first.elements, predictor, nullptr);
    advance_tangent(d, dr1, first, predictor, dpredictor, false);
    const NodeRates r2 = rates(predictor);
    const RatesTangent dr2 = rates_tangent(predictor, dpredictor, r2);
    const Rates mean = average(r1, r2);
    const RatesTangent dmean{(dr1.u + dr2.u) / 2, (dr1.dmu + dr2.dmu) / 2, (dr1.dxi + dr2.dxi) / 2};
    const StepLinearisation second = step_linearisation(mean.u);
    advance(node, mean, second.elements, out, xi_next);
    advance_tangent(d, dmean, second, out, dout, xi_next != nullptr);
    return mean.dxi;
  }

  /// Shooting residual at the final node: r_g = vee(log(gT^{-1} g_N))
  /// (docs/paper-notes.md#convention-shooting-residual), and its derivative J_r(r_g)^{-1} gamma_N.
  Tangent terminal_residual(const Node& last) const {
    return groups::log_between<G>(problem_.gT, last.g);
  }
  Directions terminal_residual_tangent(const Tangent& residual, const NodeTangent& d) const {
    return groups::right_jacobian_inverse<G>(residual) * d.gamma;
  }

  /// The rates of eq:reduced-system at a node (header comment): u = P v, mu' and xi'.
  struct Rates {
    Tangent u;
    Covector dmu, dxi;
  };
  /// The rates at a node with what their tangent-linear map reuses: P = Ad(h), zeta, ad*_v.
  struct NodeRates : Rates {
    Matrix p, coad_v;
    Covector zeta;
  };

  NodeRates rates(const Node& node) const {
    NodeRates r;
    r.p = G::Ad(node.transport);
    r.zeta = group_gradient(node);
    r.coad_v = G::ad(node.v).transpose();
    const Covector coad_v_mu = r.coad_v * node.mu;
    r.u = r.p * node.v;
    r.dxi = -coad_v_mu;
    // The terms whose coefficients vanish are skipped (P^T zeta for a declared zero gradient,
    // torsion at lambda = 1/2, curvature at lambda = 0, 1): the same values, fewer products.
    r.dmu = c_torsion_ * r.dxi;
    if constexpr (!Structure::zero_group_gradient) {
      if (!structure_.zero_group_gradient) r.dmu += r.p.transpose() * r.zeta;
    }
    if (c_curvature_ != 0) r.dmu -= c_curvature_ * (r.coad_v * node.xi);
    return r;
  }

 private:
  struct RatesTangent {
    Directions u, dmu, dxi;
  };
  /// The group elements of a step with velocity u: exp(h u) (disc-grp) and exp(a), a = -lambda h u
  /// (disc-exp).
  struct StepElements {
    groups::ElementOf<G> exp_u, exp_a;
  };
  /// The same with what the step's linearisation needs: Ad(exp(-h u)), h J_r(h u), Ad(exp(a)) and
  /// -lambda h J_l(a), each exponential computed once with its Jacobian.
  struct StepLinearisation {
    StepElements elements;
    Matrix ad_exp_minus_u, jacobian_u, ad_exp_a, jacobian_a;
  };

  /// a x as a lazy (coefficient-based) product: Eigen's default product takes a runtime-size kernel
  /// for the bounded column count; lazily, a sum of such products is one loop over the columns
  /// into the destination, without temporaries (bench_scheme measures the step). The argument
  /// may be a temporary: the expression is used within the full expression that creates it.
  static auto times(const Matrix& a, const Directions& x) { return a.lazyProduct(x); }

  static Rates average(const Rates& r1, const Rates& r2) {
    return {(r1.u + r2.u) / 2, (r1.dmu + r2.dmu) / 2, (r1.dxi + r2.dxi) / 2};
  }

  /// Matrix of x -> ad*_x mu = ad(x)^T mu (linear in the first argument).
  static Matrix coad_first(const Covector& mu) {
    Matrix m;
    for (int i = 0; i < n; ++i) m.col(i) = G::ad(Tangent::Unit(i)).transpose() * mu;
    return m;
  }

  Covector group_gradient(const Node& node) const {
    if constexpr (Structure::zero_group_gradient) {
      return Covector::Zero();
    } else {
      if (structure_.zero_group_gradient) return Covector::Zero();  // an erased model's
      return mechanics::require_finite_result(Covector(problem_.lagrangian.group_gradient(node.t, node.g, node.v)),
                                              "lagrangian.group_gradient", node.t, node.g, node.v);
    }
  }

  RatesTangent rates_tangent(const Node& node, const NodeTangent& d, const NodeRates& r) const {
    const Directions dcoad_v_mu = times(r.coad_v, d.mu) + times(coad_first(node.mu), d.v);
    RatesTangent dr;
    // u = Ad(h) v with d Ad(h) = ad(chi) Ad(h): du = [chi, u] + P dv = -ad(u) chi + P dv.
    dr.u = times(r.p, d.v) - times(G::ad(r.u), d.chi);
    dr.dxi = -dcoad_v_mu;
    dr.dmu = c_torsion_ * dr.dxi;
    if (c_curvature_ != 0) dr.dmu -= c_curvature_ * (times(r.coad_v, d.xi) + times(coad_first(node.xi), d.v));
    if constexpr (!Structure::zero_group_gradient) {
      if (!structure_.zero_group_gradient) {
        // eta = P^T zeta: d eta = P^T (ad(chi)^T zeta + dzeta).
        Directions deta = times(coad_first(r.zeta), d.chi) + times(d.hessian.gradient_g, d.gamma);
        if constexpr (!Structure::gradient_independent_of_velocity) {
          if (!structure_.gradient_independent_of_velocity) deta += times(d.hessian.gradient_v, d.v);
        }
        dr.dmu += times(r.p.transpose(), deta);
      }
    }
    return dr;
  }

  StepElements step_elements(const Tangent& u) const {
    const Tangent hu = dt_ * u;
    return {G::exp(hu), G::exp(Tangent(-problem_.lambda * hu))};
  }

  /// exp(h u) = exp(-h u)^{-1}, so that one fused exponential gives it with J_l(-h u) = J_r(h u).
  StepLinearisation step_linearisation(const Tangent& u) const {
    const Tangent hu = dt_ * u;
    const auto [exp_minus_u, right_jacobian] = groups::exp_and_left_jacobian<G>(Tangent(-hu));
    const auto [exp_a, left_jacobian] = groups::exp_and_left_jacobian<G>(Tangent(-problem_.lambda * hu));
    return {{G::inverse(exp_minus_u), exp_a},
            G::Ad(exp_minus_u),
            dt_ * right_jacobian,
            G::Ad(exp_a),
            -problem_.lambda * dt_ * left_jacobian};
  }

  void advance(const Node& node, const Rates& r, const StepElements& step, Node& out, const Covector* xi_next) const {
    out.t = next_node_time(node.t, dt_, problem_.T);
    out.g = G::compose(node.g, step.exp_u);
    out.transport = G::compose(step.exp_a, node.transport);  // disc_exp_update (transport/disc_exp.hpp)
    out.mu = node.mu + dt_ * r.dmu;
    out.xi = xi_next ? *xi_next : Covector(node.xi + dt_ * r.dxi);
    out.v = velocity(out.t, out.g, out.mu);
  }

  /// dv = M_v^{-1} (dmu - M_g gamma), the derivative of v = (dl/dv)^{-1}(mu); M_v^{-1} computed
  /// once when the model declares it constant (then M_g = 0).
  Directions velocity_tangent(const mechanics::LagrangianHessian<G>& hessian, const Directions& dmu,
                              const Directions& gamma) const {
    if constexpr (Structure::constant_momentum_hessian) {
      return times(momentum_v_inverse_, dmu);
    } else {
      if (structure_.constant_momentum_hessian) return times(momentum_v_inverse_, dmu);  // an erased model's
      return hessian.momentum_v.partialPivLu().solve(Directions(dmu - times(hessian.momentum_g, gamma)));
    }
  }

  /// The Lagrangian's second derivatives at a node; for an erased Lagrangian that reports a
  /// constant mu_v and a zero gradient, the constant blocks (M, 0, 0, 0) computed once (a typed
  /// model's analytic Hessian is as cheap and is evaluated as before).
  mechanics::LagrangianHessian<G> node_hessian(double t, const groups::ElementOf<G>& g, const Tangent& v) const {
    if constexpr (!(Structure::constant_momentum_hessian && Structure::zero_group_gradient)) {
      if (structure_.constant_momentum_hessian && structure_.zero_group_gradient) return constant_hessian_;
    }
    return mechanics::lagrangian_hessian<G>(problem_.lagrangian, t, g, v);
  }

  /// Linearisation of `advance`: g' = g exp(h u) gives gamma' = Ad(exp(-h u)) gamma + h J_r(h u) du;
  /// h' = exp(a) h with a = -lambda h u gives chi' = Ad(exp(a)) chi + J_l(a) da; and
  /// v' = (dl/dv)^{-1}(mu') gives dv' = M_v^{-1} (dmu' - M_g gamma').
  void advance_tangent(const NodeTangent& d, const RatesTangent& dr, const StepLinearisation& step, const Node& out,
                       NodeTangent& dout, bool xi_given) const {
    dout.gamma = times(step.ad_exp_minus_u, d.gamma) + times(step.jacobian_u, dr.u);
    dout.chi = times(step.ad_exp_a, d.chi) + times(step.jacobian_a, dr.u);
    dout.mu = d.mu + dt_ * dr.dmu;
    if (xi_given) {
      dout.xi.setZero(n, d.xi.cols());
    } else {
      dout.xi = d.xi + dt_ * dr.dxi;
    }
    dout.hessian = node_hessian(out.t, out.g, out.v);
    dout.v = velocity_tangent(dout.hessian, dout.mu, dout.gamma);
  }

  TransportedProblem<G, L> problem_;
  SchemeOrder order_;
  double dt_;
  double c_torsion_;    // 2 lambda - 1
  double c_curvature_;  // lambda (1 - lambda)
  /// The Lagrangian's Hessian structure at run time: its type's (Structure), or what an erased
  /// Lagrangian reports of the type it wraps.
  mechanics::RuntimeHessianStructure structure_;
  Matrix momentum_v_inverse_ = Matrix::Identity();  // (d^2 l/dv^2)^{-1} when constant (Structure)
  mechanics::LagrangianHessian<G> constant_hessian_{Matrix::Zero(), Matrix::Zero(), Matrix::Zero(), Matrix::Zero()};  // when mu_v is constant: at (g0, 0)
};

}  // namespace cartan::transported
