#pragma once
// Reduced Lagrangians and Hamiltonians on G x g and G x g* (paper §4 "Euler--Poincare and
// Lie--Poisson reductions", appendix "Right formalism"), and a Newton inverse Legendre map.
//
// A reduced Lagrangian l(t, g, v) is L(t, g, g v) (left-reduced, l_-) or L(t, g, v g)
// (right-reduced, l_+); which one a model is decides which equations it may be used with
// (eq:EP-left or eq:EP-right). The concept itself is side-agnostic: it asks for
//   value(t, g, v)          l(t, g, v)
//   momentum(t, g, v)       mu = dl/dv in g* (the reduced Legendre map)
//   group_gradient(t, g, v) zeta in g*, the trivialised dl/dg at fixed v:
//                             left-reduced:  zeta . w = d/de l(t, g exp(e w), v)  (= d(L_g)^*_e dl/dg)
//                             right-reduced: zeta . w = d/de l(t, exp(e w) g, v)  (= d(R_g)^*_e dl/dg)
//   velocity(t, g, mu)      v with momentum(t, g, v) = mu (the inverse Legendre map).
// (The transported-velocity solvers use the same interface with v the transported velocity
// and zeta the left-trivialised dl/dg.)
// A reduced Hamiltonian h(t, g, mu) provides value, velocity = dh/dmu in g, and group_gradient,
// the trivialised dh/dg at fixed mu with the same left/right convention.
// Covectors are dual-basis coordinates (group.hpp): <mu, v> = mu . v.

#include <cmath>
#include <concepts>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"

namespace cartan::mechanics {

template <class L, class G>
concept ReducedLagrangian =
    groups::LieGroup<G> && requires(const L& l, double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v,
                            const groups::CovectorOf<G>& mu) {
      { l.value(t, g, v) } -> std::convertible_to<double>;
      { l.momentum(t, g, v) } -> std::convertible_to<groups::CovectorOf<G>>;
      { l.group_gradient(t, g, v) } -> std::convertible_to<groups::CovectorOf<G>>;
      { l.velocity(t, g, mu) } -> std::convertible_to<groups::TangentOf<G>>;
    };

template <class H, class G>
concept ReducedHamiltonian =
    groups::LieGroup<G> && requires(const H& h, double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) {
      { h.value(t, g, mu) } -> std::convertible_to<double>;
      { h.velocity(t, g, mu) } -> std::convertible_to<groups::TangentOf<G>>;
      { h.group_gradient(t, g, mu) } -> std::convertible_to<groups::CovectorOf<G>>;
    };

/// Whether l(t, q, R v) = l(t, q, v) for every orthogonal R, v the components in an orthonormal
/// frame: whether a problem posed in one orthonormal frame at its first point is the same problem
/// in any other. What the type reports (`frame_invariant()`: a KineticPotential whose A is a
/// multiple of the identity, an erased Lagrangian), else false: a Lagrangian is taken to depend on
/// its frame unless it says otherwise (general::GeneralProblem::validate reads it).
template <class L>
bool frame_invariant_of(const L& lagrangian) {
  if constexpr (requires {
                  { lagrangian.frame_invariant() } -> std::convertible_to<bool>;
                }) {
    return lagrangian.frame_invariant();
  } else {
    return false;
  }
}

inline bool all_finite(double x) { return std::isfinite(x); }
/// A finite sum proves every entry finite (one pass of additions, cheaper than a comparison per
/// entry); an infinite or NaN sum may still come from finite entries that overflow, so then the
/// entries are checked one by one.
template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& x) {
  return std::isfinite(x.sum()) || x.allFinite();
}

/// Arguments up to this size are "moderate": a polynomial model of degree <= 3 cannot overflow
/// on them (1e100^3 = 1e300 < 1.8e308). Larger ones come from a diverging iterate.
inline constexpr double kModerateArgument = 1e100;

/// Whether t, g and x are finite and moderate (every entry at most kModerateArgument): where a
/// model callback's non-finite result is the model's fault, not a diverging iterate's.
template <class E, class X>
bool moderate_arguments(double t, const E& g, const X& x) {
  // allFinite first: Eigen's maxCoeff may skip a NaN entry ([1, nan] gave 1), and a NaN argument
  // (a point outside a chart, a diverging iterate) is the solver's business, not the model's fault.
  const auto moderate = [](const auto& a) { return a.allFinite() && a.cwiseAbs().maxCoeff() <= kModerateArgument; };
  return std::abs(t) <= kModerateArgument && moderate(g) && moderate(x);
}

/// `result` of the model callback `callback` (e.g. "lagrangian.momentum") at (t, g, x), or
/// ModelError naming the callback and its arguments when it is not finite although the
/// arguments are finite and moderate (every entry at most kModerateArgument): the model's fault,
/// reported at once rather than left to the solvers, which would retry (continuation in T would
/// halve T eight times first). Huge or non-finite arguments are the solver's business (a
/// diverging iterate, whose overflow is no defect of the model) and pass through.
template <class R, class E, class X>
const R& require_finite_result(const R& result, std::string_view callback, double t, const E& g, const X& x) {
  if (!all_finite(result) && moderate_arguments(t, g, x)) {
    throw ModelError(std::string(callback) + " returned a non-finite value at t = " + format_value(t) +
                                ", g = " + format_value(g) + ", argument = " + format_value(x));
  }
  return result;
}

/// The energy mu . v - l(t, g, v) of a reduced Lagrangian (conserved when l does not depend on t).
template <groups::LieGroup G, ReducedLagrangian<G> L>
double lagrangian_energy(const L& l, double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
  return l.momentum(t, g, v).dot(v) - l.value(t, g, v);
}

/// Thrown by inverse_legendre when Newton's method does not reach the tolerance.
class InverseLegendreError : public std::runtime_error {
 public:
  InverseLegendreError(const std::string& message, int iterations, double residual)
      : std::runtime_error(message), iterations_(iterations), residual_(residual) {}
  int iterations() const { return iterations_; }
  double residual() const { return residual_; }

 private:
  int iterations_;
  double residual_;
};

struct InverseLegendreOptions {
  /// Stop when |momentum(v) - mu|_inf <= tolerance * (1 + |mu|_inf).
  double tolerance = 1e-13;
  int max_iterations = 50;
  /// Relative step of the central-difference Jacobian: h = fd_step * (1 + |v|_inf). The
  /// Jacobian's O(h^2) error only slows Newton's convergence, it does not bias the root.
  double fd_step = 1e-5;
};

namespace detail {

/// Central-difference Jacobian d momentum / dv (an n x n matrix).
template <groups::LieGroup G, class Momentum>
groups::AlgebraMatrixOf<G> momentum_jacobian_fd(const Momentum& momentum, const groups::TangentOf<G>& v, double fd_step) {
  const double h = fd_step * (1 + v.cwiseAbs().maxCoeff());
  groups::AlgebraMatrixOf<G> jac;
  for (int j = 0; j < G::kDim; ++j) {
    const groups::TangentOf<G> e = groups::TangentOf<G>::Unit(j) * h;
    jac.col(j) = (groups::CovectorOf<G>(momentum(groups::TangentOf<G>(v + e))) - groups::CovectorOf<G>(momentum(groups::TangentOf<G>(v - e)))) / (2 * h);
  }
  return jac;
}

[[noreturn]] inline void throw_inverse_legendre(const std::string& problem, int iterations, double residual,
                                                 const Eigen::Ref<const Eigen::MatrixXd>& mu,
                                                 const Eigen::Ref<const Eigen::MatrixXd>& v) {
  throw InverseLegendreError("inverse_legendre: " + problem + " for mu = " + format_value(mu) + " after " +
                                 std::to_string(iterations) + " iterations: residual |momentum(v) - mu| = " +
                                 format_value(residual) + ", last v = " + format_value(v),
                             iterations, residual);
}

}  // namespace detail

/// Solves momentum(v) = mu for v by Newton's method with backtracking on |momentum(v) - mu|,
/// starting from `guess`. `momentum` maps a Tangent to a Covector (a model's dl/dv at fixed t, g);
/// `jacobian` maps a Tangent to the matrix d momentum/dv (d^2 l/dv^2, symmetric for a
/// Lagrangian). Throws InverseLegendreError (message and accessors give iterations and
/// residual) on non-convergence, a singular Jacobian or a non-finite iterate; throws
/// std::invalid_argument for non-finite mu or guess.
template <groups::LieGroup G, class Momentum, class Jacobian>
groups::TangentOf<G> inverse_legendre(const Momentum& momentum, const Jacobian& jacobian, const groups::CovectorOf<G>& mu,
                              groups::TangentOf<G> guess, const InverseLegendreOptions& options = {}) {
  require_finite(mu, "inverse_legendre", "mu");
  require_finite(guess, "inverse_legendre", "guess");
  if (!(options.tolerance > 0)) {
    throw_invalid("inverse_legendre", "options.tolerance", format_value(options.tolerance), "must be positive");
  }
  if (options.max_iterations < 0) {
    throw_invalid("inverse_legendre", "options.max_iterations", std::to_string(options.max_iterations),
                  "must be non-negative");
  }
  const double target = options.tolerance * (1 + mu.cwiseAbs().maxCoeff());
  groups::TangentOf<G> v = guess;
  groups::CovectorOf<G> r = groups::CovectorOf<G>(momentum(v)) - mu;
  double residual = r.cwiseAbs().maxCoeff();
  for (int iteration = 0;; ++iteration) {
    if (!std::isfinite(residual)) detail::throw_inverse_legendre("non-finite momentum", iteration, residual, mu, v);
    if (residual <= target) return v;
    if (iteration == options.max_iterations) detail::throw_inverse_legendre("no convergence", iteration, residual, mu, v);
    const Eigen::FullPivLU<groups::AlgebraMatrixOf<G>> lu(groups::AlgebraMatrixOf<G>(jacobian(v)));
    if (!lu.isInvertible()) detail::throw_inverse_legendre("singular Jacobian", iteration, residual, mu, v);
    const groups::TangentOf<G> step = -lu.solve(r);
    // Backtracking: halve the step until the residual decreases (at most 30 halvings).
    double scale = 1;
    for (int halving = 0; halving < 30; ++halving, scale /= 2) {
      const groups::TangentOf<G> trial = v + scale * step;
      const groups::CovectorOf<G> trial_r = groups::CovectorOf<G>(momentum(trial)) - mu;
      const double trial_residual = trial_r.cwiseAbs().maxCoeff();
      if (trial_residual < residual || halving == 29) {
        v = trial;
        r = trial_r;
        residual = trial_residual;
        break;
      }
    }
  }
}

/// As above with a central-difference Jacobian (options.fd_step).
template <groups::LieGroup G, class Momentum>
groups::TangentOf<G> inverse_legendre(const Momentum& momentum, const groups::CovectorOf<G>& mu, const groups::TangentOf<G>& guess,
                              const InverseLegendreOptions& options = {}) {
  if (!(options.fd_step > 0)) {
    throw_invalid("inverse_legendre", "options.fd_step", format_value(options.fd_step), "must be positive");
  }
  const auto fd_jacobian = [&](const groups::TangentOf<G>& v) {
    return detail::momentum_jacobian_fd<G>(momentum, v, options.fd_step);
  };
  return inverse_legendre<G>(momentum, fd_jacobian, mu, guess, options);
}

}  // namespace cartan::mechanics
