#pragma once
// Problems and independent references shared by the tests of the general solver.

#include <algorithm>
#include <cmath>
#include <string_view>

#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/principle/manifold_problem.hpp"
#include "../lie_group/paper_cases.hpp"

namespace cartan::testing {

using general::GeneralProblem;
using general::KineticPotential;

/// The same manifold with every member forwarded except has_parallel_torsion_and_curvature, so
/// that the scheme recomputes the frame components at every node (the general path).
template <class M>
struct WithoutFastPath {
  static constexpr int kDim = M::kDim, kAmbientDim = M::kAmbientDim;
  using Point = typename M::Point;
  using Vector = typename M::Vector;
  using Frame = typename M::Frame;
  using Operator = typename M::Operator;
  M inner;
  std::string_view name() const { return inner.name(); }
  Vector christoffel(const Point& q, const Vector& x, const Vector& y) const { return inner.christoffel(q, x, y); }
  Vector frame_bracket(const Vector& x, const Vector& y) const { return inner.frame_bracket(x, y); }
  Point step(const Point& q, const Vector& x) const { return inner.step(q, x); }
  Point point_velocity(const Point& q, const Vector& x) const { return manifolds::point_velocity(inner, q, x); }
  Vector difference(const Point& a, const Point& b) const { return inner.difference(a, b); }
  Operator transport_along_step(const Point& q, const Vector& x) const { return inner.transport_along_step(q, x); }
  Frame tangent_basis(const Point& q) const { return inner.tangent_basis(q); }
  auto frame_towards(const Point& a, const Point& b) const
    requires requires(const M& m) { m.frame_towards(a, b); }
  {
    return inner.frame_towards(a, b);
  }
  void validate(const Point& q, std::string_view where) const { inner.validate(q, where); }
};

/// The paper's free rigid body (inertia diag(2, 3, 4), endpoints of paper_free_body) on any
/// connection of SO(3) given as a manifold.
template <class M>
GeneralProblem<M, KineticPotential<M>> free_body_on(const M& manifold, const transported::TransportedProblem<groups::SO3, mechanics::RigidBody>& p) {
  return {manifold, KineticPotential<M>(paper_inertia()), p.T, p.N, p.g0, p.gT, std::nullopt};
}

/// Energy drift max_k |E_k - E_0| of a converged solution for l = 1/2 v^T A v - V.
template <class M>
double energy_drift(const general::GeneralSolution<M>& s, const KineticPotential<M>& l) {
  double drift = 0;
  for (std::size_t k = 0; k < s.trajectory.q.size(); ++k) {
    drift = std::max(drift, std::abs(l.energy(s.trajectory.q[k], s.trajectory.v[k]) -
                                     l.energy(s.trajectory.q[0], s.trajectory.v[0])));
  }
  return drift;
}

/// The classical spherical pendulum q'' = -G (e_z - z q) - |q'|^2 q from (q0, q'(0) = velocity),
/// integrated by RK4 with 20000 steps to time T (error ~1e-15 for |q'| T, G T^2 of order 1):
/// an independent reference for the general solver on S^2.
inline Eigen::Vector3d spherical_pendulum_endpoint(const Eigen::Vector3d& q0, const Eigen::Vector3d& velocity, double G,
                                                   double T) {
  using State = Eigen::Matrix<double, 6, 1>;
  const auto f = [&](const State& y) {
    const Eigen::Vector3d q = y.head<3>(), p = y.tail<3>();
    State dy;
    dy << p, -G * (Eigen::Vector3d::UnitZ() - q.z() * q) - p.squaredNorm() * q;
    return dy;
  };
  State y;
  y << q0, velocity;
  const int steps = 20000;
  const double h = T / steps;
  for (int k = 0; k < steps; ++k) {
    const State k1 = f(y), k2 = f(y + h / 2 * k1), k3 = f(y + h / 2 * k2), k4 = f(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return y.head<3>();
}

}  // namespace cartan::testing
