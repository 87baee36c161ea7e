#pragma once
// The verdict on a solution of the general problem (principle/manifold_problem.hpp), with the checks, report and
// thresholds of the Lie-group verifier (kernels/lie_group/verify.hpp, docs/verify.md), reading only the samples
// t_k, q_k, v_k, mu_k, Xi_k and the problem, never the solver:
//   * boundary: the separations (manifolds/geometry.hpp: |difference| where it is a logarithm, the
//     storage distance at the cut locus) of q_0 from q0 and q_N from qT, |Xi_N| / max(1, xi_scale),
//     against tol;
//   * legendre: mu_k = dl/dv(t_k, q_k, v_k);
//   * energy: E = mu.v - l is conserved for every connection when l does not depend on t
//     (docs/general-connections.md#energy);
//   * residual of the local form by three-point differences, the parallel frame rebuilt from the
//     samples (E_{k+1} = transport_along_step(q_k, difference(q_k, q_{k+1})) E_k: exact for both
//     schemes, whose steps are such pieces):
//       q' = E v,   mu' = E^T grad l + mu(T(e_i, u)) + tr(Xi E^+ R(e_i, u) E),   Xi' = -v mu^T;
//   * stationarity of the discrete transported action (action.hpp) along smooth endpoint-fixed
//     variations.

#include <algorithm>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

#include "cartan/kernels/manifold/action.hpp"
#include "cartan/kernels/manifold/along.hpp"
#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/numerics/spectrum.hpp"
#include "cartan/principle/manifold_problem.hpp"
#include "cartan/verify/assemble.hpp"

namespace cartan::general {

/// The energy threshold's constant for the general solver (verify_general).
inline constexpr double kGeneralEnergyConstant = 5.0;

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
class GeneralChecks {
 public:
  using Components = manifolds::ComponentsOf<M>;
  using Vector = manifolds::VectorOf<M>;

  /// `x` needs at least 2 samples at increasing times from 0 to T (validated by the caller):
  /// uniform for action_stationarity (the discrete action's grid), any for the other checks (a
  /// collocation solution on its own mesh).
  GeneralChecks(const GeneralProblem<M, L>& problem, GeneralTrajectory<M> x) : p_(problem), x_(std::move(x)) {
    x_.frame = transported_frames(p_, x_.q);
  }

  std::size_t size() const { return x_.t.size(); }
  /// The largest step: the resolution the thresholds are measured in (T / N on a uniform grid).
  double max_step() const {
    if (verify::is_uniform(x_.t)) return p_.T / static_cast<double>(size() - 1);
    double h = 0;
    for (std::size_t k = 0; k + 1 < size(); ++k) h = std::max(h, x_.t[k + 1] - x_.t[k]);
    return h;
  }

  double boundary_error(double xi_unit) const {
    return std::max({manifolds::separation(p_.manifold, p_.q0, x_.q.front()),
                     manifolds::separation(p_.manifold, p_.qT, x_.q.back()), x_.Xi.back().norm() / xi_unit});
  }

  double legendre_residual() const {
    double worst = 0, scale = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      const Components m = p_.lagrangian.momentum(x_.t[k], x_.q[k], x_.v[k]);
      worst = std::max(worst, (x_.mu[k] - m).norm());
      scale = std::max(scale, x_.mu[k].norm() + m.norm());
    }
    return verify::relative_to(worst, scale);
  }

  double energy_drift() const {
    auto energy = [&](std::size_t k) { return x_.mu[k].dot(x_.v[k]) - p_.lagrangian.value(x_.t[k], x_.q[k], x_.v[k]); };
    double drift = 0, scale = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      drift = std::max(drift, std::abs(energy(k) - energy(0)));
      scale = std::max(scale, std::abs(energy(k)));
    }
    return verify::relative_to(drift, scale);
  }

  /// max_k |E_k v_k| + sqrt(stiffness), the stiffness |d grad l / dq| / lambda_min(dmu/dv) by
  /// central differences along the frame: h omega is the angle one step sweeps, the resolution the
  /// thresholds are measured in. The speed is the metric's where the manifold has one (so that an
  /// isometry changes nothing: on H^2 the representation's norm of a tangent vector grows like
  /// cosh of the distance from the vertex, and exact geodesics moved far out failed as unresolved),
  /// else the representation's.
  double frequency() const {
    double speed = 0, stiffness = 0;
    const double s = 1e-5;
    for (std::size_t k = 0; k < size(); ++k) {
      const Vector u = x_.frame[k] * x_.v[k];
      const auto metric = manifolds::metric_at(p_.manifold, x_.q[k]);
      const double squared = metric ? u.dot(*metric * u) : -1.0;
      speed = std::max(speed, squared > 0 ? std::sqrt(squared) : u.norm());
      manifolds::ComponentMatrixOf<M> force, mass;
      for (int i = 0; i < M::kDim; ++i) {
        const Vector e = x_.frame[k].col(i) * s;
        force.col(i) = x_.frame[k].transpose() *
                       (gradient(k, p_.manifold.step(x_.q[k], e)) - gradient(k, p_.manifold.step(x_.q[k], Vector(-e)))) / (2 * s);
        const Components dv = Components::Unit(i) * s;
        mass.col(i) = (p_.lagrangian.momentum(x_.t[k], x_.q[k], Components(x_.v[k] + dv)) -
                       p_.lagrangian.momentum(x_.t[k], x_.q[k], Components(x_.v[k] - dv))) / (2 * s);
      }
      const manifolds::ComponentMatrixOf<M> sym = (mass + mass.transpose()) / 2;
      const double smallest = numerics::smallest_symmetric_eigenvalue(sym);
      if (smallest > 0) stiffness = std::max(stiffness, force.norm() / smallest);
    }
    return speed + std::sqrt(stiffness);
  }

  /// The local form's residual at the interior samples (header comment), each equation relative to
  /// the largest sum of its terms' magnitudes; the worst of the three.
  verify::Residual equation_residual() const {
    double worst[3] = {0, 0, 0}, scale[3] = {0, 0, 0}, where[3] = {0, 0, 0}, noise[3] = {0, 0, 0};
    for (std::size_t k = 1; k + 1 < size(); ++k) {
      // The three-point derivative at t_k for steps b = t_k - t_{k-1}, a = t_{k+1} - t_k, second
      // order on any mesh: (b^2 (f_{k+1} - f_k) + a^2 (f_k - f_{k-1})) / (a b (a + b)); on a
      // uniform one the central difference (f_{k+1} - f_{k-1}) / 2h.
      const double a = x_.t[k + 1] - x_.t[k], b = x_.t[k] - x_.t[k - 1], d = a * b * (a + b);
      const Vector dq = (b * b * difference(k, k + 1) - a * a * difference(k, k - 1)) / d;
      const Components dmu = (b * b * (x_.mu[k + 1] - x_.mu[k]) + a * a * (x_.mu[k] - x_.mu[k - 1])) / d;
      const manifolds::ComponentMatrixOf<M> dXi = (b * b * (x_.Xi[k + 1] - x_.Xi[k]) + a * a * (x_.Xi[k] - x_.Xi[k - 1])) / d;
      const auto& E = x_.frame[k];
      const Vector u = E * x_.v[k];
      const auto dual = manifolds::dual_frame<M>(E);
      const Vector mu_ambient = dual.transpose() * x_.mu[k];
      const Eigen::Matrix<double, M::kAmbientDim, M::kAmbientDim> xi_ambient = E * x_.Xi[k] * dual;
      const Components force = E.transpose() * gradient(k, x_.q[k]);
      Components torsion, curvature;
      for (int i = 0; i < M::kDim; ++i) {
        const Vector e = E.col(i);
        torsion[i] = mu_ambient.dot(manifolds::torsion(p_.manifold, x_.q[k], e, u));
        curvature[i] = (xi_ambient * manifolds::curvature_operator(p_.manifold, x_.q[k], e, u)).trace();
      }
      const manifolds::ComponentMatrixOf<M> vmu = x_.v[k] * x_.mu[k].transpose();
      const double size = x_.v[k].norm() * x_.mu[k].norm();
      const double residual[3] = {(dq - u).norm(), (dmu - force - torsion - curvature).norm(), (dXi + vmu).norm()};
      const double terms[3] = {dq.norm() + u.norm(), dmu.norm() + force.norm() + torsion.norm() + curvature.norm() + size,
                               dXi.norm() + vmu.norm()};
      const verify::ThreePoint w(b, a);  // the weights of the formula above, for its roundoff
      const double roundoff[3] = {
          verify::three_point_roundoff(w, x_.q[k - 1].norm(), x_.q[k].norm(), x_.q[k + 1].norm()),
          verify::three_point_roundoff(w, x_.mu[k - 1].norm(), x_.mu[k].norm(), x_.mu[k + 1].norm()),
          verify::three_point_roundoff(w, x_.Xi[k - 1].norm(), x_.Xi[k].norm(), x_.Xi[k + 1].norm())};
      for (int i = 0; i < 3; ++i) {
        scale[i] = std::max(scale[i], terms[i]);
        noise[i] = std::max(noise[i], roundoff[i]);
        if (residual[i] > worst[i]) worst[i] = residual[i], where[i] = x_.t[k];
      }
    }
    static const char* const kNames[3] = {"q' = E v", "mu equation", "Xi' = -v mu^T"};
    return verify::worst_equation(worst, scale, noise, where, kNames, 3);
  }

  /// The samples' roundoff against their steps (verify::step_roundoff; Figures::step_roundoff).
  double samples_roundoff() const {
    double largest = 0, longest = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      largest = std::max(largest, x_.q[k].norm());
      if (k + 1 < size()) longest = std::max(longest, difference(k, k + 1).norm());
    }
    return verify::step_roundoff(largest, longest);
  }

  /// max over `count` variations w_j(t) = sin(j pi t / T) (basis(q_k) r_j), r_j random unit, of
  /// |dS_h/de| relative to sum_k h (|mu_k| |w_j'| + |grad l| |w_j|) (what dS would be without
  /// cancellation).
  double action_stationarity(int count, unsigned seed) const {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    const double h = p_.T / static_cast<double>(size() - 1);  // uniform: verify_general checks
    double worst = 0;
    for (int j = 1; j <= count; ++j) {
      Components r;
      for (int i = 0; i < M::kDim; ++i) r[i] = normal(rng);
      r.normalize();
      const double frequency = j * std::numbers::pi / p_.T;
      std::vector<Vector> w(size(), Vector::Zero());
      double scale = 0;
      for (std::size_t k = 0; k < size(); ++k) {
        const double s = x_.t[k] * frequency;
        if (k > 0 && k + 1 < size()) w[k] = p_.manifold.tangent_basis(x_.q[k]) * r * std::sin(s);
        scale += h * (x_.mu[k].norm() * frequency * std::abs(std::cos(s)) + gradient(k, x_.q[k]).norm() * std::abs(std::sin(s)));
      }
      worst = std::max(worst, verify::relative_to(std::abs(discrete_action_derivative(p_, x_.q, w)), scale));
    }
    return worst;
  }

 private:
  Vector difference(std::size_t a, std::size_t b) const { return p_.manifold.difference(x_.q[a], x_.q[b]); }
  Vector gradient(std::size_t k, const manifolds::PointOf<M>& q) const {
    return p_.lagrangian.point_gradient(x_.t[k], q, x_.v[k]);
  }

  const GeneralProblem<M, L>& p_;
  GeneralTrajectory<M> x_;
};

/// Runs every check on `x` (t increasing from 0 to T, at least 3 samples; q, v, mu, Xi at every
/// time), a solution of `problem` to tolerance `tol` by a scheme of order `order` (1 or 2, or 4
/// for collocation, whose samples are checked at second order). Action stationarity needs uniform
/// times (the discrete action's grid): on a collocation mesh it is not applicable, and says so, as
/// in the Lie-group verifier. A status other than converged adds a failing `converged` check.
/// Throws std::invalid_argument for mismatched sizes, too few samples, times that do not increase
/// from 0 to T, a bad order or tol, and for samples off the manifold or not finite in a converged
/// result (in a failed one they are a diverged iterate's: its report fails, saying so).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
verify::Report verify_general(const GeneralProblem<M, L>& problem, const GeneralTrajectory<M>& x, int order, double tol,
                              Status status) {
  problem.validate();
  constexpr std::string_view where = "verify_general";
  require_result_order(order, where);
  require_tolerance(tol, where);
  const std::size_t n = x.t.size();
  if (n < 3 || x.q.size() != n || x.v.size() != n || x.mu.size() != n || x.Xi.size() != n) {
    std::string times = "(";  // appended, not "(" + ...: GCC 12 warns falsely on inserting a prefix (-Wrestrict)
    times += std::to_string(n) + " times)";
    throw_invalid(where, "trajectory", times, "needs q, v, mu and Xi at 3 or more times");
  }
  const bool increasing = std::adjacent_find(x.t.begin(), x.t.end(), std::greater_equal<>()) == x.t.end();
  if (!increasing || std::abs(x.t.front()) > 1e-9 * problem.T || std::abs(x.t.back() - problem.T) > 1e-9 * problem.T) {
    std::string span = "[";
    span += format_value(x.t.front()) + ", " + format_value(x.t.back()) + "]";
    throw_invalid(where, "trajectory.t", span,
                  "must increase strictly from 0 to T = " + format_value(problem.T));
  }
  try {
    for (std::size_t k = 0; k < n; ++k) {
      problem.manifold.validate(x.q[k], "trajectory.q");
      require_finite(x.v[k], where, "trajectory.v");
      require_finite(x.mu[k], where, "trajectory.mu");
      require_finite(x.Xi[k], where, "trajectory.Xi");
    }
  } catch (const std::invalid_argument& e) {
    if (status == Status::Converged) throw;
    return verify::unchecked_failure(status, e.what());  // a diverged iterate: FAIL, saying why
  }
  const GeneralChecks<M, L> checks(problem, x);
  verify::Figures f;
  f.resolution = checks.max_step() * checks.frequency();
  f.boundary = checks.boundary_error(std::max(1.0, xi_scale(problem)));
  f.boundary_note = "max(separation(q0, q_0), separation(qT, q_N), |Xi_N| / max(1, xi_scale)) against tol";
  f.legendre = checks.legendre_residual();
  f.legendre_note = "max |mu - dl/dv(q, v)|, relative";
  // Energy: the schemes are not symplectic, and away from the Lie-group case the drift is not
  // bounded in time: each step's error O((h omega)^(p+1)) E accumulates over T / h steps, so the
  // bound is C (1 + T omega) rho^p. C = 5: the largest figure measured is 2.2 (1 + T omega) rho
  // (order 1, S^2, A = diag(1, 2.5), G = 3, T omega = 2).
  const double horizon_factor = 1 + problem.T * f.resolution / checks.max_step();
  f.energy = checks.energy_drift();
  f.energy_constant = kGeneralEnergyConstant * horizon_factor;
  f.energy_note = "max |E - E(0)| / max |E|, E = mu.v - l (conserved for every connection when l does not depend on t)";
  f.residual = checks.equation_residual();
  f.residual_equations = "the local form";
  f.step_roundoff = checks.samples_roundoff();
  if (verify::is_uniform(x.t)) {
    f.stationarity = checks.action_stationarity(verify::kVariations, verify::kVariationSeed);
  } else {
    f.stationarity_note = verify::kNonUniformStationarityNote;
  }
  return verify::assemble(f, order, tol, status);
}

}  // namespace cartan::general
