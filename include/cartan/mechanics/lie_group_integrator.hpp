#pragma once
// The fixed-step Lie-group integrator shared by the reduced equations of motion
// (euler_poincare.hpp, lie_poisson.hpp, euler_lagrange.hpp): a system on G x g*
//   g' = g v      (Side::Left,  v = g^{-1} g')   or   g' = v g   (Side::Right, v = g' g^{-1}),
//   mu' = f(t, g, mu),                            v = v(t, g, mu),
// integrated by the Runge–Kutta–Munthe-Kaas method of order 4 (RKMK4, classical RK4 tableau).
// Over one step g = g_n exp(Theta) (left) or exp(Theta) g_n (right) with Theta(t_n) = 0 and
//   Theta' = dexp^{-1}_{-Theta} v = v + 1/2 [Theta, v] + 1/12 [Theta, [Theta, v]]   (left),
//   Theta' = dexp^{-1}_{Theta} v  = v - 1/2 [Theta, v] + 1/12 [Theta, [Theta, v]]   (right),
// truncated after the double bracket, which is enough for order 4 (Munthe-Kaas 1999); mu is
// advanced by classical RK4 in the same stages. g moves only by group products, so it stays on
// the group up to the rounding of those products (no projection needed).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/groups/side.hpp"

namespace cartan::mechanics {

/// All nodes t_k = k T / steps (k = 0..steps) of a reduced trajectory: the group element, the
/// velocity (left- or right-trivialised as the equations say) and the momentum in g*.
template <groups::LieGroup G>
struct Trajectory {
  std::vector<double> t;
  std::vector<groups::ElementOf<G>> g;
  std::vector<groups::TangentOf<G>> v;
  std::vector<groups::CovectorOf<G>> mu;

  void reserve(std::size_t nodes) {
    t.reserve(nodes);
    g.reserve(nodes);
    v.reserve(nodes);
    mu.reserve(nodes);
  }
  void push(double time, const groups::ElementOf<G>& element, const groups::TangentOf<G>& velocity, const groups::CovectorOf<G>& momentum) {
    t.push_back(time);
    g.push_back(element);
    v.push_back(velocity);
    mu.push_back(momentum);
  }
};

/// The right-hand side of the reduced system at one point: v and mu'.
template <groups::LieGroup G>
struct ReducedRate {
  groups::TangentOf<G> velocity;
  groups::CovectorOf<G> momentum_rate;
};

/// mu' = +ad*_v mu + force (Side::Left, eq:EP-left / eq:LP-left) or -ad*_v mu + force
/// (Side::Right, eq:EP-right / eq:LP-right); the force is zeta (EP) or -zeta_h (LP).
template <groups::LieGroup G>
groups::CovectorOf<G> coadjoint_momentum_rate(groups::Side side, const groups::TangentOf<G>& v, const groups::CovectorOf<G>& mu,
                                      const groups::CovectorOf<G>& force) {
  const double sign = side == groups::Side::Left ? 1.0 : -1.0;
  return sign * groups::coad<G>(v, mu) + force;
}

/// The truncated dexp^{-1} of the header comment (left: at -Theta, right: at Theta).
template <groups::LieGroup G>
groups::TangentOf<G> dexpinv_order4(groups::Side side, const groups::TangentOf<G>& theta, const groups::TangentOf<G>& v) {
  const double sign = side == groups::Side::Left ? 1.0 : -1.0;
  const groups::TangentOf<G> theta_v = groups::bracket<G>(theta, v);
  return v + (sign / 2) * theta_v + groups::bracket<G>(theta, theta_v) / 12;
}

/// g_n exp(Theta) (left) or exp(Theta) g_n (right).
template <groups::LieGroup G>
groups::ElementOf<G> advance(groups::Side side, const groups::ElementOf<G>& g, const groups::TangentOf<G>& theta) {
  return side == groups::Side::Left ? G::compose(g, G::exp(theta)) : G::compose(G::exp(theta), g);
}

/// Checks the common inputs of every reduced integrator; throws std::invalid_argument naming
/// `where` and the offending value.
template <groups::LieGroup G>
void validate_initial_value_problem(std::string_view where, const groups::ElementOf<G>& g0, std::string_view x0_name,
                                    const groups::TangentOf<G>& x0, double T, int steps) {
  require_finite(T, where, "T");
  if (!(T > 0)) throw_invalid(where, "T", format_value(T), "must be positive");
  if (steps < 1) throw_invalid(where, "steps", std::to_string(steps), "must be at least 1");
  G::validate(g0, "g0");
  require_finite(x0, where, x0_name);
}

/// RKMK4 over [0, T] with `steps` equal steps from (g0, mu0). `rate(t, g, mu)` returns a
/// ReducedRate<G>. Preconditions (checked by the callers): T > 0, steps >= 1, valid g0.
template <groups::LieGroup G, class Rate>
Trajectory<G> integrate_rkmk4(groups::Side side, const Rate& rate, const groups::ElementOf<G>& g0, const groups::CovectorOf<G>& mu0,
                              double T, int steps) {
  const double h = T / steps;
  Trajectory<G> out;
  out.reserve(static_cast<std::size_t>(steps) + 1);
  groups::ElementOf<G> g = g0;
  groups::CovectorOf<G> mu = mu0;
  for (int k = 0;; ++k) {
    const double t = k * h;
    const ReducedRate<G> r1 = rate(t, g, mu);
    out.push(t, g, r1.velocity, mu);
    if (k == steps) break;
    // Stage i evaluates the rate at (g exp(Theta_i), mu + M_i) and returns K_i = h dexpinv(Theta_i, v_i).
    const auto stage = [&](double dt, const groups::TangentOf<G>& theta, const groups::CovectorOf<G>& dmu, groups::TangentOf<G>& k_theta,
                           groups::CovectorOf<G>& k_mu) {
      const ReducedRate<G> r = rate(t + dt, advance<G>(side, g, theta), groups::CovectorOf<G>(mu + dmu));
      k_theta = h * dexpinv_order4<G>(side, theta, r.velocity);
      k_mu = h * r.momentum_rate;
    };
    const groups::TangentOf<G> k1 = h * r1.velocity;
    const groups::CovectorOf<G> m1 = h * r1.momentum_rate;
    groups::TangentOf<G> k2, k3, k4;
    groups::CovectorOf<G> m2, m3, m4;
    stage(h / 2, k1 / 2, m1 / 2, k2, m2);
    stage(h / 2, k2 / 2, m2 / 2, k3, m3);
    stage(h, k3, m3, k4, m4);
    g = advance<G>(side, g, groups::TangentOf<G>((k1 + 2 * k2 + 2 * k3 + k4) / 6));
    mu += (m1 + 2 * m2 + 2 * m3 + m4) / 6;
  }
  return out;
}

/// The reduced equations of eq:EP-left/right and eq:LP-left/right share one form:
///   mu' = +-ad*_v mu + force(t, g, mu, v),   v = model.velocity(t, g, mu),   g' = g v or v g,
/// where `model` is a ReducedLagrangian (velocity = inverse Legendre map) or a
/// ReducedHamiltonian (velocity = dh/dmu). Integrated with integrate_rkmk4 (preconditions as there).
template <groups::LieGroup G, class Model, class Force>
Trajectory<G> integrate_coadjoint_flow(groups::Side side, const Model& model, const Force& force, const groups::ElementOf<G>& g0,
                                       const groups::CovectorOf<G>& mu0, double T, int steps) {
  const auto rate = [&](double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) {
    const groups::TangentOf<G> v = model.velocity(t, g, mu);
    return ReducedRate<G>{v, coadjoint_momentum_rate<G>(side, v, mu, force(t, g, mu, v))};
  };
  return integrate_rkmk4<G>(side, rate, g0, mu0, T, steps);
}

}  // namespace cartan::mechanics
