#pragma once
// The transported-velocity BVP on the Heisenberg group H3 (paper appendix sec-app-H3, the
// reduced system of eq:reduced-system) as a first-order system for the collocation solver.
//
// State y = (a, b, c, v) in R^6, v the transported velocity left-trivialised at g0
// (docs/conventions.md). H3 is two-step nilpotent, so the trivialised transport from g0 to g(t)
// depends only on the endpoints (para-trans-Heis): P(t) = I - lambda ad(Delta),
// Delta = (a - a0, b - b0, 0) = int_0^t u. With a natural Lagrangian l = 1/2 v.I v - V(g),
// mu = I v and zeta = -dV(g):
//   g'  = d(L_g)_e (P v)                                 (left-Heis; reconstruction)
//   v'  = I^{-1} (P^T zeta - (2 lambda - 1) ad*_v mu)    (the curvature term vanishes on H3)
//   (a, b, c)(0) = g0,  (a, b, c)(T) = gT.
// For g0 = e and I = identity this is the six-equation system printed in the appendix; for
// g0 != e the transport keeps a0 and b0 (docs/paper-notes.md#erratum-5). The auxiliary covector
// xi' = -ad*_v mu, xi(T) = 0 of eq:reduced-system does not feed back on H3 (ad*_v xi = 0 since
// xi_3 = 0), so it is integrated afterwards along the solution (heisenberg_xi).

#include <algorithm>
#include <array>
#include <cmath>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/mechanics/natural_system.hpp"
#include "cartan/numerics/collocation.hpp"
#include "cartan/principle/group_problem.hpp"

namespace cartan::transported {

/// (para-trans-Heis) in trivialised form: P = I - lambda ad(g - g0) (only a, b enter ad).
inline groups::Heisenberg::AlgebraMatrix heisenberg_transport(double lambda, const groups::Heisenberg::Element& g0,
                                                      const groups::Heisenberg::Element& g) {
  return groups::Heisenberg::AlgebraMatrix::Identity() - lambda * groups::Heisenberg::ad(g - g0);
}

template <mechanics::Potential<groups::Heisenberg> V>
using HeisenbergNaturalProblem = TransportedProblem<groups::Heisenberg, mechanics::NaturalLagrangian<groups::Heisenberg, V>>;

/// Matrix of x -> ad*_x mu (linear in x): column i is ad*_{E_i} mu.
inline groups::Heisenberg::AlgebraMatrix coad_first(const groups::Heisenberg::Tangent& mu) {
  groups::Heisenberg::AlgebraMatrix out;
  for (int i = 0; i < 3; ++i) out.col(i) = groups::coad<groups::Heisenberg>(groups::Heisenberg::Tangent::Unit(i), mu);
  return out;
}

/// Analytic df/dy of the system below (blocks over g, v). With
/// Delta = g - g0: u = P v = v + lambda ad(v) Delta, so du/dg = lambda ad(v); g' = L(g) u with
/// L(g) = d(L_g)_e, whose a-derivative adds u2 to c'; P^T zeta = zeta - lambda ad(Delta)^T zeta
/// gives d/dg = P^T dzeta/dg - lambda coad_first(zeta), where dzeta/dg = -H L(g)^{-1} (H the
/// potential's left Hessian: g exp(e E_i) moves the coordinates by L(g) E_i); and
/// d(ad*_v I v)/dv = ad(v)^T I + coad_first(I v).
/// On H3 ad(x) w = (0, 0, x1 w2 - x2 w1) (groups/heisenberg.hpp; 1-based components), so every
/// product with ad, L(g) or P touches one row or column: they are written out below (the same
/// terms as the matrix products, without their multiplications by structural zeros).
template <mechanics::Potential<groups::Heisenberg> V>
Eigen::Matrix<double, 6, 6> heisenberg_transported_jacobian(const HeisenbergNaturalProblem<V>& problem,
                                                            const groups::Heisenberg::AlgebraMatrix& inertia_inverse,
                                                            double t, const Eigen::Matrix<double, 6, 1>& y) {
  using M3 = groups::Heisenberg::AlgebraMatrix;
  const groups::Heisenberg::Element g = y.head<3>();
  const groups::Heisenberg::Tangent v = y.segment<3>(3);
  const auto& l = problem.lagrangian;
  const double lambda = problem.lambda;
  const double d1 = g[0] - problem.g0[0], d2 = g[1] - problem.g0[1];  // Delta's a and b
  const groups::Heisenberg::Tangent mu = l.momentum(t, g, v);
  const groups::Heisenberg::Tangent zeta = l.group_gradient(t, g, v);
  const M3& inertia = l.inertia();
  // dzeta/dg = -H L(g)^{-1}, L(g)^{-1} = I - a E_3 E_2^T.
  const M3 hessian = mechanics::potential_left_hessian<groups::Heisenberg>(l.potential(), g);
  M3 force = -hessian;
  force.col(1) += g[0] * hessian.col(2);
  // P^T dzeta/dg (P^T = I - lambda ad(Delta)^T: rows 1 and 2 gain multiples of row 3), then
  // - lambda coad_first(zeta), whose columns 1 and 2 are (0, zeta3, 0) and (-zeta3, 0, 0).
  force.row(0) += lambda * d2 * force.row(2);
  force.row(1) -= lambda * d1 * force.row(2);
  force(1, 0) -= lambda * zeta[2];
  force(0, 1) += lambda * zeta[2];
  // d(ad*_v I v)/dv = ad(v)^T I + coad_first(I v): rows -v2 I_3. and v1 I_3., plus mu3 in (2, 1)
  // and -mu3 in (1, 2).
  M3 dcoad_dv = M3::Zero();
  dcoad_dv.row(0) = -v[1] * inertia.row(2);
  dcoad_dv.row(1) = v[0] * inertia.row(2);
  dcoad_dv(0, 1) -= mu[2];
  dcoad_dv(1, 0) += mu[2];
  Eigen::Matrix<double, 6, 6> dfdy = Eigen::Matrix<double, 6, 6>::Zero();
  // g' = L(g) P v = (v1, v2, v3 - lambda (d1 v2 - d2 v1) + a v2).
  dfdy(2, 0) = (1 - lambda) * v[1];
  dfdy(2, 1) = lambda * v[0];
  dfdy(0, 3) = 1;
  dfdy(1, 4) = 1;
  dfdy(2, 3) = lambda * d2;
  dfdy(2, 4) = g[0] - lambda * d1;
  dfdy(2, 5) = 1;
  dfdy.block<3, 3>(3, 0) = inertia_inverse * force;
  dfdy.block<3, 3>(3, 3) = -(2 * lambda - 1) * inertia_inverse * dcoad_dv;
  return dfdy;
}

/// The same into dfdy (6 x 6).
template <mechanics::Potential<groups::Heisenberg> V>
void heisenberg_transported_jacobian(const HeisenbergNaturalProblem<V>& problem,
                                     const groups::Heisenberg::AlgebraMatrix& inertia_inverse, double t, numerics::ConstVectorRef y,
                                     numerics::MatrixRef dfdy) {
  dfdy = heisenberg_transported_jacobian(problem, inertia_inverse, t, Eigen::Matrix<double, 6, 1>(y));
}

/// f of the system above at one point y = (a, b, c, v), with ad, P and L(g) written out as in
/// the Jacobian: u = P v = (v1, v2, v3 - lambda (d1 v2 - d2 v1)), g' = L(g) u = u + a u2 E_3,
/// P^T zeta = zeta + lambda zeta3 (d2, -d1, 0), ad*_v mu = mu3 (-v2, v1, 0).
template <mechanics::Potential<groups::Heisenberg> V>
Eigen::Matrix<double, 6, 1> heisenberg_transported_rate(const HeisenbergNaturalProblem<V>& problem, double t,
                                                        const Eigen::Matrix<double, 6, 1>& y) {
  const groups::Heisenberg::Element g = y.head<3>();
  const groups::Heisenberg::Tangent v = y.segment<3>(3);
  const auto& l = problem.lagrangian;
  const double lambda = problem.lambda;
  const double d1 = g[0] - problem.g0[0], d2 = g[1] - problem.g0[1];
  const groups::Heisenberg::Tangent mu = l.momentum(t, g, v);
  const groups::Heisenberg::Tangent zeta = l.group_gradient(t, g, v);
  const groups::Heisenberg::Tangent coad_v_mu(-v[1] * mu[2], v[0] * mu[2], 0);
  const groups::Heisenberg::Tangent transported(zeta[0] + lambda * d2 * zeta[2], zeta[1] - lambda * d1 * zeta[2],
                                                zeta[2]);
  Eigen::Matrix<double, 6, 1> dy;
  dy << v[0], v[1], v[2] - lambda * (d1 * v[1] - d2 * v[0]) + g[0] * v[1],
      l.velocity(t, g, groups::Heisenberg::Tangent(transported - (2 * lambda - 1) * coad_v_mu));
  return dy;
}

/// The system above for the collocation solver (n = 6, no parameters), with f and its Jacobian
/// also in batched form (one call per mesh sweep; numerics::BvpSystem::rhs_batch). The Jacobian
/// of f is analytic unless `analytic_jacobian` is false (forward differences then).
template <mechanics::Potential<groups::Heisenberg> V>
numerics::BvpSystem heisenberg_transported_system(const HeisenbergNaturalProblem<V>& problem, bool analytic_jacobian = true) {
  numerics::BvpSystem s;
  s.n = 6;
  s.rhs = [problem](double t, numerics::ConstVectorRef y, numerics::ConstVectorRef, numerics::VectorRef dy) {
    dy = heisenberg_transported_rate(problem, t, y);
  };
  s.rhs_batch = [problem](numerics::ConstVectorRef t, numerics::ConstMatrixRef y, numerics::ConstVectorRef,
                          numerics::MatrixRef dy) {
    for (Eigen::Index j = 0; j < t.size(); ++j) dy.col(j) = heisenberg_transported_rate(problem, t[j], y.col(j));
  };
  s.bc = [g0 = problem.g0, gT = problem.gT](numerics::ConstVectorRef ya, numerics::ConstVectorRef yb, numerics::ConstVectorRef, numerics::VectorRef r) {
    r << ya.head<3>() - g0, yb.head<3>() - gT;
  };
  s.bc_jacobian = [](numerics::ConstVectorRef, numerics::ConstVectorRef, numerics::ConstVectorRef, numerics::MatrixRef dya, numerics::MatrixRef dyb, numerics::MatrixRef) {
    dya.setZero();
    dyb.setZero();
    dya.topLeftCorner<3, 3>().setIdentity();
    dyb.bottomLeftCorner<3, 3>().setIdentity();
  };
  if (analytic_jacobian) {
    const groups::Heisenberg::AlgebraMatrix inverse = problem.lagrangian.inertia().inverse();
    s.rhs_jacobian = [problem, inverse](double t, numerics::ConstVectorRef y, numerics::ConstVectorRef,
                                        numerics::MatrixRef dfdy, numerics::MatrixRef) {
      heisenberg_transported_jacobian(problem, inverse, t, y, dfdy);
    };
    s.rhs_jacobian_batch = [problem, inverse](numerics::ConstVectorRef t, numerics::ConstMatrixRef y,
                                              numerics::ConstVectorRef, numerics::MatrixRef dfdy, numerics::MatrixRef) {
      for (Eigen::Index j = 0; j < t.size(); ++j) {
        dfdy.middleCols<6>(6 * j) = heisenberg_transported_jacobian(problem, inverse, t[j], y.col(j));
      }
    };
  }
  return s;
}

/// The geodesic initial guess on a uniform mesh of problem.N intervals: g(t) = g0 exp(t w / T),
/// v = w / T with w = log(g0^{-1} gT) (the shooting solvers' guess).
template <mechanics::Potential<groups::Heisenberg> V>
void heisenberg_geodesic_guess(const HeisenbergNaturalProblem<V>& problem, Eigen::VectorXd& t, Eigen::MatrixXd& y) {
  const groups::Heisenberg::Tangent w = groups::Heisenberg::log(groups::Heisenberg::compose(groups::Heisenberg::inverse(problem.g0), problem.gT));
  t = Eigen::VectorXd::LinSpaced(problem.N + 1, 0, problem.T);
  y.setZero(6, t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    y.col(i).head<3>() = groups::Heisenberg::compose(problem.g0, groups::Heisenberg::exp(groups::Heisenberg::Tangent(t[i] / problem.T * w)));
    y.col(i).segment<3>(3) = w / problem.T;
  }
}

/// Solves the H3 transported BVP by collocation from the geodesic guess.
template <mechanics::Potential<groups::Heisenberg> V>
numerics::BvpResult solve_heisenberg_collocation(const HeisenbergNaturalProblem<V>& problem, const numerics::CollocationOptions& options) {
  problem.validate();
  Eigen::VectorXd t;
  Eigen::MatrixXd y;
  heisenberg_geodesic_guess(problem, t, y);
  return numerics::solve_collocation(heisenberg_transported_system(problem), t, y, Eigen::VectorXd(0), options);
}

/// xi(t) = int_t^T ad*_v mu dr (eq:reduced-system, xi(T) = 0) at the given times (3 x times),
/// integrated exactly along the solution's cubic interpolant: v is cubic on each mesh interval,
/// so the integrand ad*_v I v has degree 6 there and 4-point Gauss-Legendre is exact.
template <mechanics::Potential<groups::Heisenberg> V>
Eigen::MatrixXd heisenberg_xi(const HeisenbergNaturalProblem<V>& problem, const numerics::BvpResult& solution,
                              const Eigen::VectorXd& times) {
  static constexpr std::array<double, 4> kNodes{-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                                0.8611363115940526};
  static constexpr std::array<double, 4> kWeights{0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                                  0.3478548451374538};
  const numerics::CubicHermite s = solution.interpolant();
  const auto& l = problem.lagrangian;
  auto integral = [&](double a, double b) {  // int_a^b ad*_v mu dr
    groups::Heisenberg::Tangent sum = groups::Heisenberg::Tangent::Zero();
    for (std::size_t j = 0; j < kNodes.size(); ++j) {
      const double r = (a + b) / 2 + (b - a) / 2 * kNodes[j];
      const Eigen::VectorXd y = s.value(r);
      const groups::Heisenberg::Element g = y.head<3>();
      const groups::Heisenberg::Tangent v = y.segment<3>(3);
      sum += kWeights[j] * groups::coad<groups::Heisenberg>(v, l.momentum(r, g, v));
    }
    return groups::Heisenberg::Tangent((b - a) / 2 * sum);
  };
  const Eigen::VectorXd& t = solution.t;
  const Eigen::Index m = t.size();
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(3, m);  // int_{t_i}^T
  for (Eigen::Index i = m - 2; i >= 0; --i) tail.col(i) = tail.col(i + 1) + integral(t[i], t[i + 1]);
  Eigen::MatrixXd xi(3, times.size());
  for (Eigen::Index j = 0; j < times.size(); ++j) {
    const Eigen::Index upper = std::upper_bound(t.data(), t.data() + m, times[j]) - t.data();
    const Eigen::Index i = std::clamp<Eigen::Index>(upper, 1, m - 1);  // times[j] in [t_{i-1}, t_i]
    xi.col(j) = integral(times[j], t[i]) + tail.col(i);
  }
  return xi;
}

}  // namespace cartan::transported
