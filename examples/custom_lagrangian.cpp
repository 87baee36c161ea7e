// A user-defined reduced Lagrangian (cartan/mechanics/lagrangian.hpp, concept ReducedLagrangian) solved by
// the transported-velocity solvers (eq:reduced-system): a heavy top on SO(3) whose kinetic
// energy has a quartic correction, so that the Legendre map v -> mu is nonlinear and its inverse
// comes from cartan::mechanics::inverse_legendre (Newton):
//   l(g, v) = 1/2 v.I v + eps/4 |v|^4 - c e3.(g chi),
//   mu = dl/dv = I v + eps |v|^2 v,   zeta = -c chi x (g^T e3)  (left-trivialised dl/dg).
// docs/user-guide.md "Defining a new Lagrangian" walks through this file. Run by ctest
// (examples/CMakeLists.txt); exits non-zero when one of its checks fails.
#include <cmath>
#include <cstdio>
#include <string>

#include "cartan/groups/so3.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"  // the library's solve for the erased Lagrangian

/// The four required members; no `hessian`, so the solvers differentiate momentum and
/// group_gradient by central differences (lagrangian_hessian.hpp).
class HeavyTop {
 public:
  HeavyTop(const Eigen::Vector3d& inertia, double eps, double weight, const Eigen::Vector3d& centre)
      : inertia_(inertia.asDiagonal()), eps_(eps), weight_(weight), centre_(centre) {}

  double value(double, const cartan::groups::SO3::Element& g, const cartan::groups::SO3::Tangent& v) const {
    return 0.5 * v.dot(inertia_ * v) + eps_ / 4 * v.squaredNorm() * v.squaredNorm() -
           weight_ * (g * centre_).z();
  }
  cartan::groups::SO3::Tangent momentum(double, const cartan::groups::SO3::Element&, const cartan::groups::SO3::Tangent& v) const {
    return inertia_ * v + eps_ * v.squaredNorm() * v;
  }
  /// d/de of -V(g exp(e w)): the height of g exp(e w) chi changes by (g^T e3).(w x chi).
  cartan::groups::SO3::Tangent group_gradient(double, const cartan::groups::SO3::Element& g, const cartan::groups::SO3::Tangent&) const {
    return -weight_ * centre_.cross(vertical_in_body(g));
  }
  /// The inverse Legendre map by Newton's method, with the analytic d mu/dv and the linear
  /// part's inverse as the starting guess.
  cartan::groups::SO3::Tangent velocity(double t, const cartan::groups::SO3::Element& g, const cartan::groups::SO3::Tangent& mu) const {
    const auto momentum_of = [&](const cartan::groups::SO3::Tangent& v) { return momentum(t, g, v); };
    const auto jacobian = [&](const cartan::groups::SO3::Tangent& v) { return momentum_jacobian(v); };
    return cartan::mechanics::inverse_legendre<cartan::groups::SO3>(momentum_of, jacobian, mu, inertia_.inverse() * mu);
  }

 protected:
  /// d mu/dv = I + eps (|v|^2 Id + 2 v v^T), symmetric positive definite.
  Eigen::Matrix3d momentum_jacobian(const Eigen::Vector3d& v) const {
    return inertia_ + eps_ * (v.squaredNorm() * Eigen::Matrix3d::Identity() + 2 * v * v.transpose());
  }
  Eigen::Vector3d vertical_in_body(const cartan::groups::SO3::Element& g) const { return g.transpose().col(2); }

  Eigen::Matrix3d inertia_;
  double eps_, weight_;
  Eigen::Vector3d centre_;
};
static_assert(cartan::mechanics::ReducedLagrangian<HeavyTop, cartan::groups::SO3>);

/// The same model with the optional analytic second derivatives (fewer callbacks per step).
/// g exp(e w) turns z = g^T e3 into z + e z x w, so d zeta / d gamma = -c hat(chi) hat(z).
class HeavyTopWithHessian : public HeavyTop {
 public:
  using HeavyTop::HeavyTop;
  cartan::mechanics::LagrangianHessian<cartan::groups::SO3> hessian(double, const cartan::groups::SO3::Element& g,
                                                 const cartan::groups::SO3::Tangent& v) const {
    const Eigen::Matrix3d zero = Eigen::Matrix3d::Zero();
    return {.momentum_v = momentum_jacobian(v),
            .momentum_g = zero,
            .gradient_v = zero,
            .gradient_g = -weight_ * cartan::groups::SO3::hat(centre_) * cartan::groups::SO3::hat(vertical_in_body(g))};
  }
};

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("  [%s] %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok) ++failures;
}

template <class L>
cartan::transported::TransportedSolution<cartan::groups::SO3> solve(const L& top, double lambda, int steps, double tol) {
  const cartan::groups::SO3::Element gT =
      cartan::groups::SO3::minimal_rotation(Eigen::Vector3d(-0.7, -1, -0.7), Eigen::Vector3d(0.8, 0.8, 1));
  const cartan::transported::TransportedProblem<cartan::groups::SO3, L> problem{top, lambda, 3.0, steps, cartan::groups::SO3::identity(), gT};
  cartan::transported::SolveOptions options;  // shooting, continued in T if it fails from the guess
  options.method = cartan::transported::Method::Shooting;
  options.continuation = cartan::transported::Continuation::T;
  options.order = cartan::transported::SchemeOrder::Second;
  options.tol = tol;
  // Behind the erased Lagrangian: the library's compiled solve, so this file instantiates no solver.
  return cartan::transported::solve(cartan::transported::erased(problem), options);
}

void print(const char* label, const cartan::transported::TransportedSolution<cartan::groups::SO3>& s) {
  std::printf("  %s: %s, v0 = (%.8f, %.8f, %.8f), terminal error %.2e, %d iterations, %d sweeps, %.3f s (%s)\n",
              label, std::string(cartan::to_string(s.status)).c_str(), s.v0[0], s.v0[1], s.v0[2], s.terminal_error, s.inner_iterations, s.sweeps,
              s.solve_time_s, s.branch.c_str());
}

/// max_k |E_k - E_0| of the energy mu.v - l along a solution.
double energy_drift(const HeavyTop& top, const cartan::transported::TransportedSolution<cartan::groups::SO3>& s) {
  const auto& tr = s.trajectory;
  const double e0 = cartan::mechanics::lagrangian_energy<cartan::groups::SO3>(top, tr.t[0], tr.g[0], tr.v[0]);
  double drift = 0;
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    drift = std::max(drift, std::abs(cartan::mechanics::lagrangian_energy<cartan::groups::SO3>(top, tr.t[k], tr.g[k], tr.v[k]) - e0));
  }
  return drift;
}

}  // namespace

int main() {
  const Eigen::Vector3d inertia(2, 3, 4), centre(0.1, 0.2, 1.0);
  const HeavyTop top(inertia, 0.1, 0.5, centre);
  const HeavyTopWithHessian top_hessian(inertia, 0.1, 0.5, centre);
  const double tol = 1e-10;

  std::printf("Heavy top with quartic kinetic energy on SO(3)\n");
  // The central differences (step 1e-5) are accurate to ~1e-10 (lagrangian_hessian.hpp); 1e-7
  // catches a wrong analytic formula, which would be off by O(1).
  const cartan::groups::SO3::Element g = cartan::groups::SO3::exp(Eigen::Vector3d(0.3, -0.5, 0.8));
  const Eigen::Vector3d v(0.4, -0.2, 0.7);
  const auto analytic = top_hessian.hessian(0, g, v);
  const auto differences = cartan::mechanics::lagrangian_hessian_fd<cartan::groups::SO3>(top, 0, g, v);
  const double hessian_gap = std::max({(analytic.momentum_v - differences.momentum_v).cwiseAbs().maxCoeff(),
                                       (analytic.momentum_g - differences.momentum_g).cwiseAbs().maxCoeff(),
                                       (analytic.gradient_v - differences.gradient_v).cwiseAbs().maxCoeff(),
                                       (analytic.gradient_g - differences.gradient_g).cwiseAbs().maxCoeff()});
  std::printf("  analytic hessian - central differences: %.2e\n", hessian_gap);
  check(hessian_gap < 1e-7, "the analytic hessian matches central differences");
  const Eigen::Vector3d mu = top.momentum(0, g, v);
  const double legendre_gap = (top.velocity(0, g, mu) - v).norm();
  std::printf("  inverse Legendre map: |velocity(momentum(v)) - v| = %.2e\n", legendre_gap);
  check(legendre_gap < 1e-12, "velocity inverts momentum");

  std::printf("Transported-velocity BVP, lambda = 1/2, T = 3, N = 300, order 2, tol %.0e\n", tol);
  const auto s_fd = solve(top, 0.5, 300, tol);
  const auto s_analytic = solve(top_hessian, 0.5, 300, tol);
  print("differences", s_fd);
  print("analytic   ", s_analytic);
  check(s_fd.converged() && s_fd.terminal_error <= tol, "converged with difference-quotient second derivatives");
  check(s_analytic.converged() && s_analytic.terminal_error <= tol, "converged with the analytic hessian");
  // Both solve the same discrete equations to tol = 1e-10 on the residual; the second
  // derivatives only steer Newton (measured: the two v0 agree to 2e-16). 1e-8 = 100 tol allows
  // for the residual's conditioning (a wrong hessian slows or stops Newton, it cannot move the root).
  const double v0_gap = (s_fd.v0 - s_analytic.v0).norm();
  std::printf("  |v0(differences) - v0(analytic)| = %.2e\n", v0_gap);
  check(v0_gap < 1e-8, "both reach the same solution");

  // lambda = 0 is the classical Euler-Poincare motion (eq:EP-left), whose energy mu.v - l is
  // conserved; the order-2 scheme conserves it to O(h^2), so halving h must divide the drift by
  // about 4 (a ratio above 3 means order > 1.58).
  std::printf("Energy mu.v - l at lambda = 0 (conserved by eq:EP-left)\n");
  const double drift_coarse = energy_drift(top, solve(top_hessian, 0.0, 300, tol));
  const double drift_fine = energy_drift(top, solve(top_hessian, 0.0, 600, tol));
  std::printf("  max drift N = 300: %.3e, N = 600: %.3e, ratio %.2f (observed order %.2f)\n", drift_coarse, drift_fine,
              drift_coarse / drift_fine, std::log2(drift_coarse / drift_fine));
  check(drift_coarse / drift_fine > 3, "energy drift falls at second order");

  std::printf("%s\n", failures == 0 ? "all checks passed" : "SOME CHECKS FAILED");
  return failures == 0 ? 0 : 1;
}
