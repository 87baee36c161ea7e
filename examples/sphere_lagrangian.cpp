// Your own Lagrangian on a manifold with a connection (cartan/mechanics/manifold_lagrangian.hpp, concept
// ManifoldLagrangian), solved by the library's compiled general solve: behind
// general::ErasedLagrangian it needs no solver instantiation of its own, so this file compiles in
// seconds (bench/README.md, "Build time"). A bead on the unit sphere whose inertia grows with
// height, under gravity:
//   l(q, v) = 1/2 (1 + eps z^2) |v|^2 - G z,   z = q_3, v the transported velocity (2 components),
//   mu = (1 + eps z^2) v,   zeta = (eps z |v|^2 - G) e_3 (the ambient gradient in q, v held).
// Checks (exit status non-zero when one fails): the solve converges and verify_general passes; at
// eps = 0 it is the built-in KineticPotential's solution; the discrete energy
// 1/2 (1 + eps z^2)|v|^2 + G z drifts by O(h^2) (order 2: a quarter when N doubles).
#include <cmath>
#include <cstdio>

#include "cartan/kernels/manifold/compiled.hpp"

namespace {

using cartan::manifolds::Sphere;
using Point = Eigen::Vector3d;      // a point of S^2 in R^3
using Components = Eigen::Vector2d;  // v and mu in the frame chosen at q0

class HeavyBead {
 public:
  HeavyBead(double eps, double gravity) : eps_(eps), gravity_(gravity) {}
  double value(double, const Point& q, const Components& v) const {
    return 0.5 * inertia(q) * v.squaredNorm() - gravity_ * q.z();
  }
  Components momentum(double, const Point& q, const Components& v) const { return inertia(q) * v; }
  Components velocity(double, const Point& q, const Components& mu) const { return mu / inertia(q); }
  Point point_gradient(double, const Point& q, const Components& v) const {
    return Point(0, 0, eps_ * q.z() * v.squaredNorm() - gravity_);
  }
  double energy(const Point& q, const Components& v) const {
    return 0.5 * inertia(q) * v.squaredNorm() + gravity_ * q.z();
  }

 private:
  double inertia(const Point& q) const { return 1 + eps_ * q.z() * q.z(); }
  double eps_, gravity_;
};

bool check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  return ok;
}

cartan::general::ErasedProblem<Sphere> problem(const cartan::general::ErasedLagrangian<Sphere>& l, int N) {
  return {Sphere{}, l, 1.5, N, cartan::manifolds::sphere_point({1, 0, -0.3}), cartan::manifolds::sphere_point({0, 1, -0.5}),
          std::nullopt};
}

cartan::SolveOptions second_order() {
  cartan::SolveOptions options;
  options.order = cartan::SchemeOrder::Second;
  options.tol = 1e-12;
  return options;
}

}  // namespace

int main() {
  using namespace cartan;
  const HeavyBead bead(0.8, 9.81);
  bool ok = true;
  double drift[2] = {0, 0};
  for (int refinement = 0; refinement < 2; ++refinement) {
    const auto p = problem(general::ErasedLagrangian<Sphere>(bead), 200 << refinement);
    const general::GeneralSolution<Sphere> s = general::solve(p, second_order());
    ok &= check(s.converged(), s.message.c_str());
    const verify::Report report = general::verify_general(p, s.trajectory, s.order, 1e-12, s.status);
    ok &= check(report.passed(), "verify_general passes");
    if (!s.converged()) return 1;
    double low = INFINITY, high = -INFINITY;
    for (std::size_t k = 0; k < s.trajectory.q.size(); ++k) {
      const double e = bead.energy(s.trajectory.q[k], s.trajectory.v[k]);
      low = std::min(low, e), high = std::max(high, e);
    }
    drift[refinement] = high - low;
    std::printf("N = %d: %d iterations, energy drift %.3e\n", p.N, s.inner_iterations, drift[refinement]);
  }
  // Order 2: the drift falls by 4 when h halves (2.6 to 5.5 allows for the leading term's rounding
  // at these step sizes).
  ok &= check(drift[0] / drift[1] > 2.6 && drift[0] / drift[1] < 5.5, "the energy drift is O(h^2)");

  // eps = 0 is l = 1/2 |v|^2 - G z, the built-in KineticPotential with identity inertia.
  const auto mine = general::solve(problem(general::ErasedLagrangian<Sphere>(HeavyBead(0, 9.81)), 200), second_order());
  const auto builtin = general::solve(
      problem(general::ErasedLagrangian<Sphere>(general::KineticPotential<Sphere>::with_linear_potential(
                  Eigen::Matrix2d::Identity(), Eigen::Vector3d(0, 0, 9.81))),
              200),
      second_order());
  // Both converge to |r| <= 1e-12 on the same discrete equations (the roots' sensitivity is O(1)).
  ok &= check(mine.converged() && builtin.converged() && (mine.v0 - builtin.v0).norm() < 1e-9,
              "at eps = 0 the built-in KineticPotential's solution");
  return ok ? 0 : 1;
}
