#pragma once
// Independent checks of a sampled solution of the transported-velocity BVP (paper §6,
// eq:reduced-system; `cartan verify`, docs/verify.md). They read only the samples t_k, g_k, v_k,
// mu_k, xi_k and the problem (Lagrangian, lambda, T, g0, gT), never the solver:
//   * boundary: |log(g0^{-1} g_0)|, |log(gT^{-1} g_N)| and |xi_N| (xi(T) = 0);
//   * Legendre: mu_k = dl/dv(t_k, g_k, v_k);
//   * energy E = mu.v - l: along eq:reduced-system d/dt(1/2 v.I v) = v.mu' = v.P^T zeta = u.zeta,
//     because v.ad*_v(.) = 0 kills the torsion and curvature terms for EVERY lambda; for
//     l = 1/2 v.I v - V(g), u.zeta = -dV/dt, so E = 1/2 v.I v + V(g) is conserved for every lambda
//     (not only lambda in {0, 1});
//   * residual of the continuous equations by finite differences (below);
//   * stationarity of the discrete transported action (kernels/lie_group/action.hpp) along random smooth
//     endpoint-fixed variations.
// Each check returns a dimensionless figure (a relative size); the thresholds come from the
// scheme's order and the resolution h * omega (discretisation_threshold).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cartan/kernels/lie_group/action.hpp"
#include "cartan/kernels/lie_group/along.hpp"
#include "cartan/kernels/lie_group/scheme.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"
#include "cartan/numerics/spectrum.hpp"
#include "cartan/verify/figures.hpp"

namespace cartan::verify {

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
class TrajectoryChecks {
 public:
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;

  /// `trajectory` needs at least 2 samples with increasing t on [0, T] (validated by the caller,
  /// e.g. cli::read_result). The transport P_k = Ad(h_k) is rebuilt from the samples alone:
  /// h_0 = e, h_{k+1} = exp(-lambda log(g_k^{-1} g_{k+1})) h_k (disc-exp with the step's mean
  /// velocity; exact for both shooting schemes, whose steps are g_{k+1} = g_k exp(h u), and
  /// second order otherwise; exact on H3, where P depends on g - g0 only, para-trans-Heis).
  TrajectoryChecks(L lagrangian, double lambda, double T, transported::TransportedTrajectory<G> trajectory)
      : l_(std::move(lagrangian)), lambda_(lambda), T_(T), x_(std::move(trajectory)),
        transport_(transported::transport_elements<G>(lambda_, x_.g)) {}

  std::size_t size() const { return x_.t.size(); }
  const transported::TransportedTrajectory<G>& trajectory() const { return x_; }

  /// max(|log(g0^{-1} g_0)|, |log(gT^{-1} g_N)|, |xi_N| / xi_unit): the boundary conditions in
  /// the units of the solvers' tolerances (radians; xi relative to xi_unit, see verify_trajectory).
  double boundary_error(const groups::ElementOf<G>& g0, const groups::ElementOf<G>& gT, double xi_unit = 1.0) const {
    return std::max({groups::log_between<G>(g0, x_.g.front()).norm(),
                     groups::log_between<G>(gT, x_.g.back()).norm(), x_.xi.back().norm() / xi_unit});
  }

  /// max_k |mu_k - dl/dv(g_k, v_k)| / max_k (|mu_k| + |dl/dv|): the Legendre relation, which
  /// every solver imposes exactly (to rounding).
  double legendre_residual() const {
    double worst = 0, scale = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      const Covector m = l_.momentum(x_.t[k], x_.g[k], x_.v[k]);
      worst = std::max(worst, (x_.mu[k] - m).norm());
      scale = std::max(scale, x_.mu[k].norm() + m.norm());
    }
    return relative_to(worst, scale);
  }

  /// A characteristic angular frequency of the motion: max_k |u_k| (u = P v, the group
  /// velocity) plus the potential's frequency sqrt(|d zeta/dg| / lambda_min(d mu/dv)).
  /// h omega is the angle a step sweeps: the resolution the thresholds are measured in.
  double frequency() const {
    double speed = 0, stiffness = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      speed = std::max(speed, (G::Ad(transport_[k]) * x_.v[k]).norm());
      const mechanics::LagrangianHessian<G> hess = mechanics::lagrangian_hessian<G>(l_, x_.t[k], x_.g[k], x_.v[k]);
      const groups::AlgebraMatrixOf<G> mass = (hess.momentum_v + hess.momentum_v.transpose()) / 2;
      const double smallest = numerics::smallest_symmetric_eigenvalue(mass);
      if (smallest > 0) stiffness = std::max(stiffness, hess.gradient_g.norm() / smallest);
    }
    return speed + std::sqrt(stiffness);
  }

  /// How much faster than omega the coadjoint terms of the mu equation can move mu:
  /// a = max(1, |2 lambda - 1| + |lambda (1 - lambda)| kappa), kappa = max_k |ad*_v xi| / max_k
  /// |ad*_v mu| (the curvature term's operand against the torsion term's; 0/0 = 0). On
  /// lambda in [0, 1] a = 1 whenever kappa <= 2 (the measured calibration range); outside it the
  /// torsion coefficient |2 lambda - 1| > 1 and the curvature coefficient grow, and the scheme's
  /// error with them (docs/verify.md#lambda-outside-0-1).
  double amplification() const {
    double torsion_operand = 0, curvature_operand = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      torsion_operand = std::max(torsion_operand, groups::coad<G>(x_.v[k], x_.mu[k]).norm());
      curvature_operand = std::max(curvature_operand, groups::coad<G>(x_.v[k], x_.xi[k]).norm());
    }
    const double kappa = relative_to(curvature_operand, torsion_operand);
    return std::max(1.0, std::abs(2 * lambda_ - 1) + std::abs(lambda_ * (1 - lambda_)) * kappa);
  }

  /// The largest step of t.
  double max_step() const {
    double h = 0;
    for (std::size_t k = 0; k + 1 < size(); ++k) h = std::max(h, x_.t[k + 1] - x_.t[k]);
    return h;
  }

  /// max_k |E_k - E_0| / max_k |E_k| with E = mu.v - l (lagrangian_energy): conserved for every
  /// lambda along eq:reduced-system when l does not depend on t (see the top of this file).
  double energy_drift() const {
    const double e0 = energy(0);
    double drift = 0, scale = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      const double e = energy(k);
      drift = std::max(drift, std::abs(e - e0));
      scale = std::max(scale, std::abs(e));
    }
    return relative_to(drift, scale);
  }

  /// Residual of eq:reduced-system in the solvers' form (kernels/lie_group/scheme.hpp) at the interior
  /// samples, derivatives by the three-point formula (second order on any mesh):
  ///   g:  u - P v = 0,                       u = g^{-1} g' (from log(g_k^{-1} g_{k+-1}))
  ///   mu: mu' - P^T zeta + (2 lambda - 1) ad*_v mu + lambda (1 - lambda) ad*_v xi = 0
  ///   xi: xi' + ad*_v mu = 0
  /// Each equation's residual is relative to the largest sum of the magnitudes of its terms (and
  /// |v| |mu| in the covector equations) over the samples; the largest of the three is returned.
  /// Needs at least 3 samples (else 0).
  Residual equation_residual() const {
    double worst[3] = {0, 0, 0}, scale[3] = {0, 0, 0}, where[3] = {0, 0, 0}, noise[3] = {0, 0, 0};
    const double torsion = 2 * lambda_ - 1, curvature = lambda_ * (1 - lambda_);
    for (std::size_t k = 1; k + 1 < size(); ++k) {
      const ThreePoint d(x_.t[k] - x_.t[k - 1], x_.t[k + 1] - x_.t[k]);
      const Tangent u = d.a * Tangent(-step_log(k - 1)) + d.c * step_log(k);  // log(g_k^{-1} g_{k-1}) = -step_log(k-1)
      const Covector dmu = d.a * x_.mu[k - 1] + d.b * x_.mu[k] + d.c * x_.mu[k + 1];
      const Covector dxi = d.a * x_.xi[k - 1] + d.b * x_.xi[k] + d.c * x_.xi[k + 1];
      const auto p = G::Ad(transport_[k]);
      const Tangent pv = p * x_.v[k];
      const Covector force = p.transpose() * l_.group_gradient(x_.t[k], x_.g[k], x_.v[k]);
      const Covector coad_mu = groups::coad<G>(x_.v[k], x_.mu[k]);
      const Covector coad_xi = groups::coad<G>(x_.v[k], x_.xi[k]);
      const double residual[3] = {(u - pv).norm(),
                                  (dmu - force + torsion * coad_mu + curvature * coad_xi).norm(),
                                  (dxi + coad_mu).norm()};
      // |v| |mu| bounds ad*_v mu up to a constant: the size the coadjoint terms have before the
      // cancellation in the bracket (so rounding in a steady rotation is not compared with 0).
      const double coadjoint_size = x_.v[k].norm() * x_.mu[k].norm();
      const double terms[3] = {u.norm() + pv.norm(),
                               dmu.norm() + force.norm() + coadjoint_size + std::abs(torsion) * coad_mu.norm() +
                                   std::abs(curvature) * coad_xi.norm(),
                               dxi.norm() + coadjoint_size + coad_mu.norm()};
      // u comes from log(g_k^-1 g_{k+-1}): a product's roundoff, of size |g_k^-1| |g_j|.
      const double inverse = G::inverse(x_.g[k]).norm();
      const double roundoff[3] = {
          three_point_roundoff(d, inverse * x_.g[k - 1].norm(), inverse * x_.g[k].norm(), inverse * x_.g[k + 1].norm()),
          three_point_roundoff(d, x_.mu[k - 1].norm(), x_.mu[k].norm(), x_.mu[k + 1].norm()),
          three_point_roundoff(d, x_.xi[k - 1].norm(), x_.xi[k].norm(), x_.xi[k + 1].norm())};
      for (int i = 0; i < 3; ++i) {
        scale[i] = std::max(scale[i], terms[i]);
        noise[i] = std::max(noise[i], roundoff[i]);
        if (residual[i] > worst[i]) worst[i] = residual[i], where[i] = x_.t[k];
      }
    }
    static const char* const kNames[3] = {"g' = g P v", "mu equation", "xi' = -ad*_v mu"};
    return worst_equation(worst, scale, noise, where, kNames, 3);
  }

  /// The samples' roundoff against their steps (step_roundoff; Figures::step_roundoff): the
  /// samples' size is that of the products g_k^-1 g_{k+1} the steps are logarithms of.
  double samples_roundoff() const {
    double largest = 0, longest = 0;
    for (std::size_t k = 0; k + 1 < size(); ++k) {
      largest = std::max(largest, G::inverse(x_.g[k]).norm() * x_.g[k + 1].norm());
      longest = std::max(longest, step_log(k).norm());
    }
    return step_roundoff(largest, longest);
  }

  /// max over `count` variations w_j(t) = sin(j pi t / T) r_j (j = 1..count, r_j random unit
  /// vectors from `seed`) of |dS_h/de| along g_k -> g_k exp(e w_j(t_k)) (kernels/lie_group/action.hpp),
  /// relative to the size of the first-variation integrand's terms,
  /// sum_k h (|mu_k| |w_j'(t_k)| + |zeta_k| |w_j(t_k)|): what dS would be without cancellation.
  /// Needs uniform t (is_uniform): the discrete action is defined on a uniform mesh.
  double action_stationarity(int count, unsigned seed) const {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    const double h = T_ / static_cast<double>(size() - 1);
    double worst = 0;
    for (int j = 1; j <= count; ++j) {
      Tangent r;
      for (int i = 0; i < G::kDim; ++i) r[i] = normal(rng);
      r.normalize();
      const double frequency = j * std::numbers::pi / T_;
      std::vector<Tangent> w(size());
      double scale = 0;
      for (std::size_t k = 0; k < size(); ++k) {
        const double s = x_.t[k] * frequency;
        w[k] = (k == 0 || k + 1 == size()) ? Tangent(Tangent::Zero()) : Tangent(std::sin(s) * r);
        scale += h * (x_.mu[k].norm() * frequency * std::abs(std::cos(s)) +
                      l_.group_gradient(x_.t[k], x_.g[k], x_.v[k]).norm() * std::abs(std::sin(s)));
      }
      const double derivative = transported::transported_action_derivative<G>(l_, lambda_, T_, x_.g, w);
      worst = std::max(worst, relative_to(std::abs(derivative), scale));
    }
    return worst;
  }

 private:
  /// log(g_k^{-1} g_{k+1}).
  Tangent step_log(std::size_t k) const { return groups::log_between<G>(x_.g[k], x_.g[k + 1]); }
  double energy(std::size_t k) const { return mechanics::lagrangian_energy<G>(l_, x_.t[k], x_.g[k], x_.v[k]); }

  L l_;
  double lambda_, T_;
  transported::TransportedTrajectory<G> x_;
  std::vector<groups::ElementOf<G>> transport_;
};

}  // namespace cartan::verify
