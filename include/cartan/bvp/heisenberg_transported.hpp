#pragma once
// The transported-velocity BVP on the Heisenberg group H3 (paper appendix sec-app-H3, the
// reduced system of eq:reduced-system) as a first-order system for the collocation solver.
//
// State y = (a, b, c, v, xi) in R^9, v the transported velocity left-trivialised at g0
// (docs/conventions.md), xi the auxiliary covector of eq:reduced-system. H3 is two-step
// nilpotent, so the trivialised transport from g0 to g(t) depends only on the endpoints
// (para-trans-Heis): P(t) = I - lambda ad(Delta), Delta = (a - a0, b - b0, 0) = int_0^t u.
// With a natural Lagrangian l = 1/2 v.I v - V(g), mu = I v and zeta = -dV(g):
//   g'  = d(L_g)_e (P v)                                 (left-Heis; reconstruction)
//   v'  = I^{-1} (P^T zeta - (2 lambda - 1) ad*_v mu)    (the curvature term vanishes on H3)
//   xi' = -ad*_v mu,   xi(T) = 0
//   (a, b, c)(0) = g0,  (a, b, c)(T) = gT.
// For g0 = e and I = identity this is the six-equation system printed in the appendix; for
// g0 != e the transport keeps a0 and b0 (PAPER-NOTES erratum 5).

#include <cmath>

#include "cartan/bvp/collocation.hpp"
#include "cartan/heisenberg.hpp"
#include "cartan/models/natural_system.hpp"
#include "cartan/transported/problem.hpp"

namespace cartan::bvp {

/// (para-trans-Heis) in trivialised form: P = I - lambda ad(g - g0) (only a, b enter ad).
inline Heisenberg::AlgebraMatrix heisenberg_transport(double lambda, const Heisenberg::Element& g0,
                                                      const Heisenberg::Element& g) {
  return Heisenberg::AlgebraMatrix::Identity() - lambda * Heisenberg::ad(g - g0);
}

template <Potential<Heisenberg> V>
using HeisenbergNaturalProblem = TransportedProblem<Heisenberg, NaturalLagrangian<Heisenberg, V>>;

/// The system above for the collocation solver (n = 9, no parameters; finite-difference Jacobians).
template <Potential<Heisenberg> V>
BvpSystem heisenberg_transported_system(const HeisenbergNaturalProblem<V>& problem) {
  BvpSystem s;
  s.n = 9;
  s.rhs = [problem](double t, ConstVectorRef y, ConstVectorRef, VectorRef dy) {
    const Heisenberg::Element g = y.head<3>();
    const Heisenberg::Tangent v = y.segment<3>(3);
    const auto& l = problem.lagrangian;
    const Heisenberg::AlgebraMatrix transport = heisenberg_transport(problem.lambda, problem.g0, g);
    const Heisenberg::Tangent coad_v_mu = coad<Heisenberg>(v, l.momentum(t, g, v));
    dy.head<3>() = Heisenberg::left_translate(g, transport * v);
    dy.segment<3>(3) =
        l.velocity(t, g, transport.transpose() * l.group_gradient(t, g, v) - (2 * problem.lambda - 1) * coad_v_mu);
    dy.tail<3>() = -coad_v_mu;
  };
  s.bc = [g0 = problem.g0, gT = problem.gT](ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef, VectorRef r) {
    r << ya.head<3>() - g0, yb.head<3>() - gT, yb.tail<3>();
  };
  return s;
}

/// The geodesic initial guess on a uniform mesh of problem.N intervals: g(t) = g0 exp(t w / T),
/// v = w / T with w = log(g0^{-1} gT) (the shooting solvers' guess), xi = 0.
template <Potential<Heisenberg> V>
void heisenberg_geodesic_guess(const HeisenbergNaturalProblem<V>& problem, Eigen::VectorXd& t, Eigen::MatrixXd& y) {
  const Heisenberg::Tangent w = Heisenberg::log(Heisenberg::compose(Heisenberg::inverse(problem.g0), problem.gT));
  t = Eigen::VectorXd::LinSpaced(problem.N + 1, 0, problem.T);
  y.setZero(9, t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    y.col(i).head<3>() = Heisenberg::compose(problem.g0, Heisenberg::exp(Heisenberg::Tangent(t[i] / problem.T * w)));
    y.col(i).segment<3>(3) = w / problem.T;
  }
}

/// Solves the H3 transported BVP by collocation from the geodesic guess.
template <Potential<Heisenberg> V>
BvpResult solve_heisenberg_collocation(const HeisenbergNaturalProblem<V>& problem, const CollocationOptions& options) {
  problem.validate();
  Eigen::VectorXd t;
  Eigen::MatrixXd y;
  heisenberg_geodesic_guess(problem, t, y);
  return solve_collocation(heisenberg_transported_system(problem), t, y, Eigen::VectorXd(0), options);
}

}  // namespace cartan::bvp
