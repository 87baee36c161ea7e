#pragma once
// Check your own model: a ReducedLagrangian's callbacks (lagrangian.hpp) against each other, at
// sample points (t, g, v). A sign error or a wrong factor in a callback does not stop the
// solvers from "converging" (to the solution of another problem, with an energy drift); this
// names the callback instead.
//
//   momentum        mu = dl/dv           against central differences of value along v + e E_i
//   group_gradient  zeta = trivialised   against central differences of value along g exp(e E_i)
//                   dl/dg                (options.side = Right: exp(e E_i) g), lagrangian.hpp
//   velocity        the inverse Legendre velocity(momentum(v)) = v and momentum(velocity(mu)) = mu,
//                   map                  mu = the reversed momentum(v) (a second momentum of the same size)
//   hessian.<block> the model's analytic against central differences of momentum and group_gradient
//                   hessian (if any)     along v + e E_i and g exp(e E_i) (LagrangianHessian's convention)
//
// Usage:
//   const auto report = cartan::mechanics::check_lagrangian<cartan::groups::SO3>(my_lagrangian);
//   if (!report.ok()) std::cerr << report.text();  // names each failing callback and its discrepancy
// Samples are seeded pseudo-random (CheckLagrangianOptions: count, seed, scale) or given.
//
// Errors are relative with a floor: |a - d|_inf / max(|a|_inf, |d|_inf, e), where a is the
// callback's result, d the reference and e the reference's own absolute error (below). A model
// multiplied by 1e8 or 1e-8 gets the same discrepancies; a derivative that is zero (the free
// body's group gradient) is compared at the level of the differences' noise, not 0/0.
//
// Central differences D_h = (f(x + h) - f(x - h)) / 2h have the error h^2 |f'''| / 6 (truncation)
// + eps_f |f| / h (rounding of f, eps_f ~ 1e-14 for a few dozen flops). h = kCheckStep (1 + |x|_inf)
// with kCheckStep = 1e-5 balances them near (3 eps)^(1/3) ~ 9e-6: a correct derivative agrees to
// ~1e-10 relative. The error is estimated at every sample as e = |D_h - D_2h|_inf (D_2h - D_h
// = 3 h^2 f'''/6 + ..., so this is three times the truncation) + kRoundingEps max|f| / h. A check
// fails where the discrepancy exceeds max(kCheckThreshold, kErrorSafety e_rel): 1e-6 is 1e4 above
// the differences' accuracy and 1e6 below what a wrong sign, factor or missing term gives (O(1)).
// The inverse relations of `velocity` have no differences: threshold kInverseThreshold = 1e-8,
// room for a Newton inverse (inverse_legendre stops at 1e-13) on a Legendre map of condition
// number up to 1e5.
//
// A non-finite value or an exception (std::exception) in a callback is reported against the
// check that called it (note, discrepancy +inf), never thrown.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cartan/groups/side.hpp"
#include "cartan/mechanics/check_report.hpp"
#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"
#include "cartan/mechanics/lie_group_integrator.hpp"

namespace cartan::mechanics {

inline constexpr double kCheckStep = 1e-5;         ///< relative step of the central differences
inline constexpr double kRoundingEps = 1e-14;      ///< relative rounding assumed of a callback's value
inline constexpr double kCheckThreshold = 1e-6;    ///< relative discrepancy above which a derivative fails
inline constexpr double kErrorSafety = 10;         ///< ... or above this multiple of the reference's own error
inline constexpr double kInverseThreshold = 1e-8;  ///< relative discrepancy of the velocity/momentum inverse

/// One sample point of a check.
template <groups::LieGroup G>
struct LagrangianSample {
  double t = 0;
  groups::ElementOf<G> g = G::identity();
  groups::TangentOf<G> v = groups::TangentOf<G>::Zero();
};

/// The seeded samples of `options` (std::mt19937 mapped to [-1, 1] by hand, so that the points are
/// the same with every standard library). Throws std::invalid_argument for samples < 1 or a scale
/// that is not finite and positive.
template <groups::LieGroup G>
std::vector<LagrangianSample<G>> lagrangian_samples(const CheckLagrangianOptions& options) {
  if (options.samples < 1) throw_invalid("check_lagrangian", "samples", std::to_string(options.samples), "must be at least 1");
  if (!(std::isfinite(options.scale) && options.scale > 0)) {
    throw_invalid("check_lagrangian", "scale", format_value(options.scale), "must be finite and positive");
  }
  std::mt19937 rng(options.seed);
  const auto uniform = [&] { return (static_cast<double>(rng()) + 0.5) / 4294967296.0 * 2 - 1; };  // (-1, 1)
  const auto tangent = [&] {
    groups::TangentOf<G> x;
    for (int i = 0; i < G::kDim; ++i) x[i] = options.scale * uniform();
    return x;
  };
  std::vector<LagrangianSample<G>> out;
  for (int k = 0; k < options.samples; ++k) {
    const double t = options.scale * (uniform() + 1) / 2;
    const groups::ElementOf<G> g = G::exp(tangent());
    out.push_back({t, g, tangent()});
  }
  return out;
}

namespace detail {

/// A central difference of f (a vector-valued function of the step e) at e = 0, with the
/// estimate of its own absolute error (the header's comment).
template <class F>
auto central_difference(const F& f, double h) {
  const auto plus = f(h), minus = f(-h), plus2 = f(2 * h), minus2 = f(-2 * h);
  using V = std::decay_t<decltype(plus)>;
  struct Result {
    V derivative;
    double error;
  };
  const V d1 = (plus - minus) / (2 * h), d2 = (plus2 - minus2) / (4 * h);
  const double size = std::max({plus.cwiseAbs().maxCoeff(), minus.cwiseAbs().maxCoeff(), plus2.cwiseAbs().maxCoeff(),
                                minus2.cwiseAbs().maxCoeff()});
  return Result{d1, (d1 - d2).cwiseAbs().maxCoeff() + kRoundingEps * size / h};
}

/// The Jacobian of f (a vector-valued function of a step x in R^Cols) at 0 by central differences
/// along the unit vectors with step h, and the largest error estimate of its columns.
template <int Cols, int Rows, class F>
auto difference_jacobian_in(const F& f, double h) {
  struct Result {
    Eigen::Matrix<double, Rows, Cols> jacobian;
    double error = 0;
  };
  Result out;
  for (int i = 0; i < Cols; ++i) {
    const auto column = central_difference(
        [&](double e) { return Eigen::Matrix<double, Rows, 1>(f(Eigen::Matrix<double, Cols, 1>::Unit(i) * e)); }, h);
    out.jacobian.col(i) = column.derivative;
    out.error = std::max(out.error, column.error);
  }
  return out;
}

/// The same along a group's tangent steps x (algebra coordinates).
template <groups::LieGroup G, int Rows, class F>
auto difference_jacobian(const F& f, double h) {
  return difference_jacobian_in<G::kDim, Rows>(f, h);
}

/// The relative discrepancy of a callback's result `a` with the reference `d` whose absolute
/// error is `error`, and that error relative to the same size (the header's comment).
struct Discrepancy {
  double discrepancy;
  double reference_error;
};
template <class A, class D>
Discrepancy relative_discrepancy(const A& a, const D& d, double error) {
  if (!all_finite(a) || !all_finite(d)) return {std::numeric_limits<double>::infinity(), 0};
  const double size = std::max({a.cwiseAbs().maxCoeff(), d.cwiseAbs().maxCoeff(), error});
  if (size == 0) return {0, 0};
  return {(a - d).cwiseAbs().maxCoeff() / size, error / size};
}

/// One check accumulated over the samples: the sample whose discrepancy is largest relative to
/// its threshold is the one reported.
class CheckAccumulator {
 public:
  CheckAccumulator(std::string callback, std::string reference) {
    check_.callback = std::move(callback);
    check_.reference = std::move(reference);
  }
  /// Records sample k (described by `at`); threshold = max(base, kErrorSafety reference_error).
  void add(int k, const std::string& at, Discrepancy d, double base, std::string note = {}) {
    const double threshold = std::max(base, kErrorSafety * d.reference_error);
    const bool ok = d.discrepancy <= threshold;
    const double ratio = d.discrepancy / threshold;
    if (check_.sample < 0 || ratio > worst_) {
      worst_ = ratio;
      check_.discrepancy = d.discrepancy, check_.reference_error = d.reference_error, check_.threshold = threshold;
      check_.sample = k, check_.at = at, check_.note = std::move(note);
    }
    check_.ok = check_.ok && ok;
  }
  /// Records an exception thrown at sample k.
  void add_exception(int k, const std::string& at, const std::exception& e) {
    add(k, at, {std::numeric_limits<double>::infinity(), 0}, 0, std::string("threw: ") + e.what());
  }
  CallbackCheck result() const { return check_; }

 private:
  CallbackCheck check_;
  double worst_ = 0;
};

/// The note for a non-finite comparison: which side was not finite.
template <class A, class D>
std::string finiteness_note(const A& a, const D& d, const std::string& callback, const std::string& reference) {
  if (!all_finite(a)) return callback + " returned a non-finite value";
  if (!all_finite(d)) return reference + " returned a non-finite value near the sample";
  return {};
}

/// The report's entry for a model without its own hessian: not checked (`gradient`: the name of the
/// model's gradient callback).
inline CallbackCheck no_analytic_hessian(const std::string& gradient) {
  CallbackCheck none;
  none.callback = "hessian";
  none.reference = "differences of momentum and " + gradient;
  none.checked = false;
  none.note = "no analytic hessian: the solvers difference momentum and " + gradient;
  return none;
}

/// Runs one sample of a check: body() returns {discrepancy, note}; an exception is recorded.
template <class Body>
void run_sample(CheckAccumulator& acc, int k, const std::string& at, double base, const Body& body) {
  try {
    auto [d, note] = body();
    acc.add(k, at, d, base, std::move(note));
  } catch (const std::exception& e) {
    acc.add_exception(k, at, e);
  }
}

/// momentum and group_gradient against differences of value at one sample.
template <groups::LieGroup G, class L>
void check_first_derivatives(const L& l, const LagrangianSample<G>& s, groups::Side side, int k, const std::string& at,
                             CheckAccumulator& momentum, CheckAccumulator& gradient) {
  using Scalar = Eigen::Matrix<double, 1, 1>;
  const double hv = kCheckStep * (1 + s.v.cwiseAbs().maxCoeff());
  run_sample(momentum, k, at, kCheckThreshold, [&] {
    const groups::CovectorOf<G> mu = l.momentum(s.t, s.g, s.v);
    const auto fd = difference_jacobian<G, 1>([&](const groups::TangentOf<G>& x) { return Scalar(l.value(s.t, s.g, s.v + x)); }, hv);
    const groups::CovectorOf<G> d = fd.jacobian.transpose();
    return std::pair{relative_discrepancy(mu, d, fd.error), finiteness_note(mu, d, "momentum", "value")};
  });
  run_sample(gradient, k, at, kCheckThreshold, [&] {
    const groups::CovectorOf<G> zeta = l.group_gradient(s.t, s.g, s.v);
    const auto fd = difference_jacobian<G, 1>(
        [&](const groups::TangentOf<G>& x) { return Scalar(l.value(s.t, mechanics::advance<G>(side, s.g, x), s.v)); }, kCheckStep);
    const groups::CovectorOf<G> d = fd.jacobian.transpose();
    return std::pair{relative_discrepancy(zeta, d, fd.error), finiteness_note(zeta, d, "group_gradient", "value")};
  });
}

/// velocity(momentum(v)) = v and momentum(velocity(mu)) = mu at one sample (the larger discrepancy),
/// with `momentum` and `velocity` the callbacks at the sample's t and point (Vector: their type).
template <class Vector, class Momentum, class Velocity>
void check_inverse(const Momentum& momentum, const Velocity& velocity, const Vector& v, int k, const std::string& at,
                   CheckAccumulator& acc) {
  run_sample(acc, k, at, kInverseThreshold, [&] {
    const Vector mu = momentum(v);
    const Vector back = velocity(mu);
    const Vector mu2 = mu.reverse();
    const Vector w = velocity(mu2);
    const Vector forth = momentum(w);
    const Discrepancy a = relative_discrepancy(back, v, 0), b = relative_discrepancy(forth, mu2, 0);
    std::string note = !all_finite(mu) ? "momentum returned a non-finite value"
                       : !all_finite(back) || !all_finite(w) ? "velocity returned a non-finite value"
                       : !all_finite(forth) ? "momentum returned a non-finite value" : "";
    return std::pair{a.discrepancy >= b.discrepancy ? a : b, note};
  });
}

template <groups::LieGroup G, class L>
void check_velocity(const L& l, const LagrangianSample<G>& s, int k, const std::string& at, CheckAccumulator& velocity) {
  check_inverse([&](const groups::TangentOf<G>& v) { return groups::CovectorOf<G>(l.momentum(s.t, s.g, v)); },
                [&](const groups::CovectorOf<G>& mu) { return groups::TangentOf<G>(l.velocity(s.t, s.g, mu)); }, s.v, k, at,
                velocity);
}

/// The four blocks of the model's hessian against differences of momentum and group_gradient.
template <groups::LieGroup G, class L>
void check_hessian(const L& l, const LagrangianSample<G>& s, int k, const std::string& at, std::vector<CheckAccumulator>& blocks) {
  const double hv = kCheckStep * (1 + s.v.cwiseAbs().maxCoeff());
  const auto mu_v = [&](const groups::TangentOf<G>& x) { return groups::CovectorOf<G>(l.momentum(s.t, s.g, s.v + x)); };
  const auto mu_g = [&](const groups::TangentOf<G>& x) { return groups::CovectorOf<G>(l.momentum(s.t, G::compose(s.g, G::exp(x)), s.v)); };
  const auto zeta_v = [&](const groups::TangentOf<G>& x) { return groups::CovectorOf<G>(l.group_gradient(s.t, s.g, s.v + x)); };
  const auto zeta_g = [&](const groups::TangentOf<G>& x) {
    return groups::CovectorOf<G>(l.group_gradient(s.t, G::compose(s.g, G::exp(x)), s.v));
  };
  std::optional<LagrangianHessian<G>> analytic;
  const auto block = [&](std::size_t index, const auto& f, double h, auto member, const char* reference) {
    run_sample(blocks[index], k, at, kCheckThreshold, [&] {
      if (!analytic) analytic = LagrangianHessian<G>(l.hessian(s.t, s.g, s.v));
      const auto fd = difference_jacobian<G, G::kDim>(f, h);
      const groups::AlgebraMatrixOf<G>& a = (*analytic).*member;
      return std::pair{relative_discrepancy(a, fd.jacobian, fd.error),
                       finiteness_note(a, fd.jacobian, blocks[index].result().callback, reference)};
    });
  };
  block(0, mu_v, hv, &LagrangianHessian<G>::momentum_v, "momentum");
  block(1, mu_g, kCheckStep, &LagrangianHessian<G>::momentum_g, "momentum");
  block(2, zeta_v, hv, &LagrangianHessian<G>::gradient_v, "group_gradient");
  block(3, zeta_g, kCheckStep, &LagrangianHessian<G>::gradient_g, "group_gradient");
}

template <groups::LieGroup G>
std::string describe(const LagrangianSample<G>& s) {
  return "t = " + format_value(s.t) + ", g = " + format_value(s.g) + ", v = " + format_value(s.v);
}

}  // namespace detail

/// Whether check_lagrangian checks the model's hessian: a `has_hessian()` member decides when the
/// model has one (an adapter whose hessian may fall back to differences), else a `hessian`
/// member returning LagrangianHessian<G>.
template <groups::LieGroup G, class L>
bool has_analytic_hessian(const L& l) {
  if constexpr (requires { { l.has_hessian() } -> std::convertible_to<bool>; }) {
    return l.has_hessian();
  } else {
    return requires(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) {
      { l.hessian(t, g, v) } -> std::convertible_to<LagrangianHessian<G>>;
    };
  }
}

/// Checks `l` at the given samples (side: how its group_gradient is trivialised). Throws
/// std::invalid_argument for no samples or a sample that is not finite.
template <groups::LieGroup G, ReducedLagrangian<G> L>
CheckReport check_lagrangian(const L& l, const std::vector<LagrangianSample<G>>& samples,
                             groups::Side side = groups::Side::Left) {
  if (samples.empty()) throw_invalid("check_lagrangian", "samples", "(none)", "must not be empty");
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& s = samples[k];
    if (!std::isfinite(s.t) || !all_finite(s.g) || !all_finite(s.v)) {
      throw_invalid("check_lagrangian", "sample " + std::to_string(k), detail::describe<G>(s), "is not finite");
    }
  }
  const std::string gradient_reference = side == groups::Side::Left ? "differences of value along g exp(e E_i)"
                                                                     : "differences of value along exp(e E_i) g";
  detail::CheckAccumulator momentum("momentum", "differences of value along v + e E_i");
  detail::CheckAccumulator gradient("group_gradient", gradient_reference);
  detail::CheckAccumulator velocity("velocity", "the inverse of momentum");
  std::vector<detail::CheckAccumulator> blocks;
  for (const char* name : {"momentum_v", "momentum_g", "gradient_v", "gradient_g"}) {
    const bool of_momentum = name[0] == 'm', along_v = name[std::string_view(name).size() - 1] == 'v';
    blocks.emplace_back(std::string("hessian.") + name, std::string("differences of ") + (of_momentum ? "momentum" : "group_gradient") +
                                                            (along_v ? " along v + e E_i" : " along g exp(e E_i)"));
  }
  const bool hessian = has_analytic_hessian<G>(l);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const std::string at = detail::describe<G>(samples[k]);
    const int index = static_cast<int>(k);
    detail::check_first_derivatives<G>(l, samples[k], side, index, at, momentum, gradient);
    detail::check_velocity<G>(l, samples[k], index, at, velocity);
    if constexpr (requires { l.hessian(samples[k].t, samples[k].g, samples[k].v); }) {
      if (hessian) detail::check_hessian<G>(l, samples[k], index, at, blocks);
    }
  }
  CheckReport report;
  report.samples = static_cast<int>(samples.size());
  for (const auto* acc : {&momentum, &gradient, &velocity}) report.checks.push_back(acc->result());
  if (hessian) {
    for (const auto& acc : blocks) report.checks.push_back(acc.result());
  } else {
    report.checks.push_back(detail::no_analytic_hessian("group_gradient"));
  }
  return report;
}

/// Checks `l` at options.samples seeded samples (lagrangian_samples).
template <groups::LieGroup G, ReducedLagrangian<G> L>
CheckReport check_lagrangian(const L& l, const CheckLagrangianOptions& options = {}) {
  return check_lagrangian<G>(l, lagrangian_samples<G>(options), options.side);
}

}  // namespace cartan::mechanics
