#pragma once
// A naive reference for the cost of one step of the paper's scheme (order 1) on SO(3): the
// discrete equations (disc-grp, disc-body-v, disc-exp, disc-Legendre, disc-aux, disc-mmt-eqn)
// for a natural Lagrangian l = 1/2 v.Iv - V(g) with V(g) = 1/2 (3 - tr g) or V = 0, written as
// one fixed-size loop with nothing shared: Rodrigues' formula inline, the inverse inertia
// applied as a product. bench_scheme.cpp times cartan's primal step against it and checks that
// both reach the same final state.

#include <Eigen/Dense>
#include <cmath>

namespace cartan::bench {

struct ReferenceState {
  Eigen::Matrix3d g, transport;
  Eigen::Vector3d mu, xi, v;
};

inline Eigen::Matrix3d reference_exp(const Eigen::Vector3d& w) {
  const double t = w.norm();
  Eigen::Matrix3d k;
  k << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  const double a = t < 1e-4 ? 1 - t * t / 6 : std::sin(t) / t;
  const double b = t < 1e-4 ? 0.5 - t * t / 24 : (1 - std::cos(t)) / (t * t);
  return Eigen::Matrix3d::Identity() + a * k + b * k * k;
}

/// N steps of size h from v0 (xi0 = 0, g0 = I) with inertia `inertia` and Cartan–Schouten
/// parameter lambda; `oscillator` selects V(g) = 1/2 (3 - tr g), else V = 0.
inline ReferenceState reference_sweep(const Eigen::Matrix3d& inertia, bool oscillator, double lambda, double h, int N,
                                      const Eigen::Vector3d& v0) {
  const Eigen::Matrix3d inverse_inertia = inertia.inverse();
  const double c_torsion = 2 * lambda - 1, c_curvature = lambda * (1 - lambda);
  ReferenceState s{Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity(), inertia * v0, Eigen::Vector3d::Zero(), v0};
  for (int k = 0; k < N; ++k) {
    const Eigen::Vector3d u = s.transport * s.v;  // P = Ad(h) = h on SO(3)
    Eigen::Vector3d zeta = Eigen::Vector3d::Zero();
    if (oscillator) {  // -dV = -vee(Skew g)
      zeta << s.g(1, 2) - s.g(2, 1), s.g(2, 0) - s.g(0, 2), s.g(0, 1) - s.g(1, 0);
      zeta /= 2;
    }
    const Eigen::Vector3d coad_v_mu = -s.v.cross(s.mu), coad_v_xi = -s.v.cross(s.xi);  // ad*_v = -v x
    const Eigen::Vector3d dmu = s.transport.transpose() * zeta - c_torsion * coad_v_mu - c_curvature * coad_v_xi;
    s.g = s.g * reference_exp(h * u);
    s.transport = reference_exp(-lambda * h * u) * s.transport;
    s.mu += h * dmu;
    s.xi -= h * coad_v_mu;
    s.v = inverse_inertia * s.mu;
  }
  return s;
}

}  // namespace cartan::bench
