#pragma once
// Charts with connections and Hamiltonians shared by the tests of kernels/manifold/hamilton.hpp and
// manifolds/bundle.hpp: the sphere in its stereographic chart with its Levi-Civita connection and
// with three other connections (added torsion: same geodesic spray; an added symmetric part:
// same torsion (none), another spray; both), and R^2 with constant connections (one with torsion
// and curvature, one metric with torsion).

#include <string>
#include <utility>
#include <vector>

#include "cartan/kernels/manifold/hamilton.hpp"
#include "cartan/manifolds/euclidean.hpp"
#include "cartan/manifolds/stereographic.hpp"

namespace cartan::testing {

using manifolds::Chart;
using manifolds::Euclidean;

/// S^k_ij = eps_ij w^k(x), antisymmetric in ij: torsion 2 eps_ij w^k, the same spray.
inline Chart<2>::Coefficients antisymmetric_part(const Eigen::Vector2d& x) {
  const Eigen::Vector2d w(0.7 + 0.3 * x.x(), -0.4 + 0.5 * x.x() * x.y());
  Chart<2>::Coefficients c;
  c[0].setZero(), c[1].setZero();
  c[0].col(1) = w;   // S^k_01 = w^k
  c[1].col(0) = -w;  // S^k_10 = -w^k
  return c;
}

/// B^k_ij symmetric in ij, varying with x: no torsion, another geodesic spray.
inline Chart<2>::Coefficients symmetric_part(const Eigen::Vector2d& x) {
  Chart<2>::Coefficients c;
  c[0] << 0.5 + x.y(), -0.3, 0.2 * x.x(), 0.6;
  c[1] << -0.3, 0.4 * x.x() * x.x(), 0.6, -0.8 + 0.1 * x.y();
  return c;
}

/// The sphere's stereographic chart with `extra` added to its Christoffel symbols.
template <class Extra>
Chart<2> sphere_chart_plus(const Extra& extra, const std::string& name) {
  const Chart<2> sphere = manifolds::stereographic_chart<1>();
  return Chart<2>(
      [sphere, extra](const Eigen::Vector2d& x) {
        Chart<2>::Coefficients c = sphere.coefficients(x);
        const Chart<2>::Coefficients e = extra(x);
        for (int i = 0; i < 2; ++i) c[i] += e[i];
        return c;
      },
      {}, name);
}

/// The four connections on the sphere's chart (header comment), Levi-Civita first.
inline std::vector<std::pair<std::string, Chart<2>>> sphere_connections() {
  const auto both = [](const Eigen::Vector2d& x) {
    Chart<2>::Coefficients c = antisymmetric_part(x);
    const Chart<2>::Coefficients s = symmetric_part(x);
    for (int i = 0; i < 2; ++i) c[i] += s[i];
    return c;
  };
  return {{"Levi-Civita", manifolds::stereographic_chart<1>()},
          {"Levi-Civita + torsion", sphere_chart_plus(antisymmetric_part, "sphere+torsion")},
          {"Levi-Civita + symmetric part", sphere_chart_plus(symmetric_part, "sphere+symmetric")},
          {"Levi-Civita + both", sphere_chart_plus(both, "sphere+both")}};
}

/// Constant Gamma^k_ij on R^2 with torsion and curvature.
inline Euclidean<2> skew_euclidean() {
  Euclidean<2>::Coefficients c;
  c[0] << 0.3, -0.5, 0.8, 0.1;
  c[1] << -0.2, 0.6, 0.4, -0.7;
  return Euclidean<2>(c);
}

/// Gamma_i = a_i J, J the rotation generator: metric for the Euclidean metric, flat (the Gamma_i
/// commute), torsion T(x, y) = (a.x) J y - (a.y) J x.
inline Euclidean<2> metric_torsion_euclidean() {
  const Eigen::Matrix2d J = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();
  return Euclidean<2>(Euclidean<2>::Coefficients{0.8 * J, -0.5 * J});
}

/// H = 1/2 p^T g^{-1} p - G q3(x) on the sphere's chart: the spherical pendulum (hanging at the
/// north pole x = 0), V = -G (1 - |x|^2) / (1 + |x|^2), grad V = 4 G x / (1 + |x|^2)^2.
inline general::KineticPotentialHamiltonian<Chart<2>> sphere_pendulum_hamiltonian(double G) {
  const Chart<2> chart = manifolds::stereographic_chart<1>();
  return general::KineticPotentialHamiltonian<Chart<2>>(
      [chart](const Eigen::Vector2d& x) { return *chart.metric(x); },
      [G](const Eigen::Vector2d& x) { return -G * (1 - x.squaredNorm()) / (1 + x.squaredNorm()); },
      [G](const Eigen::Vector2d& x) -> Eigen::Vector2d {
        const double d = 1 + x.squaredNorm();
        return 4 * G * x / (d * d);
      });
}

/// The anharmonic potential V = 1/2 |q|^2 + 1/4 q1^2 q2^2 on R^2 and its gradient.
inline double anharmonic(const Eigen::Vector2d& q) {
  return 0.5 * q.squaredNorm() + 0.25 * q.x() * q.x() * q.y() * q.y();
}
inline Eigen::Vector2d anharmonic_gradient(const Eigen::Vector2d& q) {
  return {q.x() + 0.5 * q.x() * q.y() * q.y(), q.y() + 0.5 * q.x() * q.x() * q.y()};
}

/// H = 1/2 p^T M^{-1} p + V(q) on R^2 with the anharmonic V.
inline general::KineticPotentialHamiltonian<Euclidean<2>> euclidean_hamiltonian(const Eigen::Matrix2d& mass) {
  return general::KineticPotentialHamiltonian<Euclidean<2>>::constant(mass, anharmonic, anharmonic_gradient);
}

}  // namespace cartan::testing
