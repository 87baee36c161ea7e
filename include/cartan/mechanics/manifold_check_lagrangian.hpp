#pragma once
// Check your own manifold Lagrangian (manifold_lagrangian.hpp) as mechanics::check_lagrangian checks
// a group's: its callbacks against each other at sample points (t, q, v), with the same
// differences, relative discrepancies, thresholds and report (check_lagrangian.hpp).
//
//   momentum        mu = dl/dv            against central differences of value along v + e e_i
//   point_gradient  zeta, ambient, with   against central differences of value along
//                   zeta . x = d/de l     step(q, e E_i), E = tangent_basis(q) (only the
//                   (t, step(q, e x), v)  components E^T zeta are defined: zeta's normal part on a
//                                         quadric is anything)
//   velocity        the inverse Legendre  velocity(momentum(v)) = v, momentum(velocity(mu)) = mu
//                   map
//   hessian.<block> hessian(manifold, t,  against central differences of momentum and
//                   q, v), if any         point_gradient along v + e e_i and step(q, e E_i), the
//                                         point blocks on E (E^T for a gradient's rows)
//
// A wrong point_gradient does not stop the solvers from "converging", to the solution of another
// problem; this names the callback instead. Seeded samples are taken around a point `base`:
// q = step(base, scale E x), v = scale y with x, y uniform in [-1, 1]^m, t uniform in [0, scale].
// Compiled in the library for the erased Lagrangian on the shipped manifolds (extern template in
// kernels/manifold/compiled.hpp, src/methods/solve_<manifold>.cpp).

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/mechanics/check_lagrangian.hpp"
#include "cartan/mechanics/check_report.hpp"
#include "cartan/mechanics/manifold_lagrangian.hpp"

namespace cartan::general {

/// options.samples seeded samples around `base` (the header's comment; std::mt19937 mapped by hand,
/// as mechanics::lagrangian_samples). Throws std::invalid_argument for samples < 1, a scale that
/// is not finite and positive, or a base point the manifold refuses.
template <manifolds::ManifoldWithConnection M>
std::vector<ManifoldLagrangianSample<M>> lagrangian_samples(const M& manifold, const manifolds::PointOf<M>& base,
                                                            const mechanics::CheckLagrangianOptions& options) {
  constexpr int m = M::kDim;
  if (options.samples < 1) throw_invalid("check_lagrangian", "samples", std::to_string(options.samples), "must be at least 1");
  if (!(std::isfinite(options.scale) && options.scale > 0)) {
    throw_invalid("check_lagrangian", "scale", format_value(options.scale), "must be finite and positive");
  }
  manifold.validate(base, "check_lagrangian: q");
  std::mt19937 rng(options.seed);
  const auto uniform = [&] { return (static_cast<double>(rng()) + 0.5) / 4294967296.0 * 2 - 1; };  // (-1, 1)
  const auto components = [&] {
    manifolds::ComponentsOf<M> x;
    for (int i = 0; i < m; ++i) x[i] = options.scale * uniform();
    return x;
  };
  const manifolds::FrameOf<M> frame = manifold.tangent_basis(base);
  std::vector<ManifoldLagrangianSample<M>> out;
  for (int k = 0; k < options.samples; ++k) {
    const double t = options.scale * (uniform() + 1) / 2;
    const manifolds::PointOf<M> q = manifold.step(base, manifolds::VectorOf<M>(frame * components()));
    out.push_back({t, q, components()});
  }
  return out;
}

namespace detail {

template <manifolds::ManifoldWithConnection M>
std::string describe(const ManifoldLagrangianSample<M>& s) {
  return "t = " + format_value(s.t) + ", q = " + format_value(s.q) + ", v = " + format_value(s.v);
}

/// The point q moved along the tangent basis: step(q, E x).
template <manifolds::ManifoldWithConnection M>
auto moved_along(const M& manifold, const manifolds::PointOf<M>& q, const manifolds::FrameOf<M>& frame) {
  return [&manifold, &q, &frame](const manifolds::ComponentsOf<M>& x) {
    return manifolds::PointOf<M>(manifold.step(q, manifolds::VectorOf<M>(frame * x)));
  };
}

/// momentum, point_gradient and velocity at one sample.
template <manifolds::ManifoldWithConnection M, class L>
void check_callbacks(const M& manifold, const L& l, const ManifoldLagrangianSample<M>& s, int k, const std::string& at,
                     mechanics::detail::CheckAccumulator& momentum, mechanics::detail::CheckAccumulator& gradient,
                     mechanics::detail::CheckAccumulator& velocity) {
  using namespace mechanics::detail;
  constexpr int m = M::kDim;
  using Components = manifolds::ComponentsOf<M>;
  using Scalar = Eigen::Matrix<double, 1, 1>;
  const double hv = mechanics::kCheckStep * (1 + s.v.cwiseAbs().maxCoeff());
  run_sample(momentum, k, at, mechanics::kCheckThreshold, [&] {
    const Components mu = l.momentum(s.t, s.q, s.v);
    const auto fd = difference_jacobian_in<m, 1>([&](const Components& x) { return Scalar(l.value(s.t, s.q, s.v + x)); }, hv);
    const Components d = fd.jacobian.transpose();
    return std::pair{relative_discrepancy(mu, d, fd.error), finiteness_note(mu, d, "momentum", "value")};
  });
  run_sample(gradient, k, at, mechanics::kCheckThreshold, [&] {
    const manifolds::FrameOf<M> frame = manifold.tangent_basis(s.q);
    const Components zeta = frame.transpose() * manifolds::VectorOf<M>(l.point_gradient(s.t, s.q, s.v));
    const auto moved = moved_along(manifold, s.q, frame);
    const auto fd = difference_jacobian_in<m, 1>([&](const Components& x) { return Scalar(l.value(s.t, moved(x), s.v)); },
                                                 mechanics::kCheckStep);
    const Components d = fd.jacobian.transpose();
    return std::pair{relative_discrepancy(zeta, d, fd.error), finiteness_note(zeta, d, "point_gradient", "value")};
  });
  check_inverse([&](const Components& w) { return Components(l.momentum(s.t, s.q, w)); },
                [&](const Components& mu) { return Components(l.velocity(s.t, s.q, mu)); }, s.v, k, at, velocity);
}

/// The four blocks of the Lagrangian's hessian(manifold, t, q, v) against differences, the point
/// blocks on the tangent basis (LagrangianHessian's convention: q perturbed along pieces).
template <manifolds::ManifoldWithConnection M, class L>
void check_hessian(const M& manifold, const L& l, const ManifoldLagrangianSample<M>& s, int k, const std::string& at,
                   std::vector<mechanics::detail::CheckAccumulator>& blocks) {
  using namespace mechanics::detail;
  constexpr int m = M::kDim;
  using Components = manifolds::ComponentsOf<M>;
  const double hv = mechanics::kCheckStep * (1 + s.v.cwiseAbs().maxCoeff());
  const manifolds::FrameOf<M> frame = manifold.tangent_basis(s.q);
  const auto moved = moved_along(manifold, s.q, frame);
  const auto gradient = [&](const manifolds::PointOf<M>& q, const Components& v) {
    return Components(frame.transpose() * manifolds::VectorOf<M>(l.point_gradient(s.t, q, v)));
  };
  std::optional<LagrangianHessian<M>> analytic;
  const auto block = [&](std::size_t index, const auto& f, double h, const auto& of_analytic, const char* reference) {
    run_sample(blocks[index], k, at, mechanics::kCheckThreshold, [&] {
      if (!analytic) analytic = LagrangianHessian<M>(l.hessian(manifold, s.t, s.q, s.v));
      const auto fd = difference_jacobian_in<m, m>(f, h);
      const Eigen::Matrix<double, m, m> a = of_analytic(*analytic);
      return std::pair{relative_discrepancy(a, fd.jacobian, fd.error),
                       finiteness_note(a, fd.jacobian, blocks[index].result().callback, reference)};
    });
  };
  block(0, [&](const Components& x) { return Components(l.momentum(s.t, s.q, s.v + x)); }, hv,
        [](const LagrangianHessian<M>& h) { return h.momentum_v; }, "momentum");
  block(1, [&](const Components& x) { return Components(l.momentum(s.t, moved(x), s.v)); }, mechanics::kCheckStep,
        [&](const LagrangianHessian<M>& h) { return Eigen::Matrix<double, m, m>(h.momentum_q * frame); }, "momentum");
  block(2, [&](const Components& x) { return gradient(s.q, s.v + x); }, hv,
        [&](const LagrangianHessian<M>& h) { return Eigen::Matrix<double, m, m>(frame.transpose() * h.gradient_v); },
        "point_gradient");
  block(3, [&](const Components& x) { return gradient(moved(x), s.v); }, mechanics::kCheckStep,
        [&](const LagrangianHessian<M>& h) { return Eigen::Matrix<double, m, m>(frame.transpose() * h.gradient_q * frame); },
        "point_gradient");
}

}  // namespace detail

/// Checks `l` on `manifold` at the given samples (the header's comment). Throws
/// std::invalid_argument for no samples or a sample that is not finite or not on the manifold.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
mechanics::CheckReport check_lagrangian(const M& manifold, const L& l, const std::vector<ManifoldLagrangianSample<M>>& samples) {
  if (samples.empty()) throw_invalid("check_lagrangian", "samples", "(none)", "must not be empty");
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& s = samples[k];
    if (!std::isfinite(s.t) || !mechanics::all_finite(s.v)) {
      throw_invalid("check_lagrangian", "sample " + std::to_string(k), detail::describe<M>(s), "is not finite");
    }
    manifold.validate(s.q, "check_lagrangian: sample " + std::to_string(k));
  }
  using mechanics::detail::CheckAccumulator;
  CheckAccumulator momentum("momentum", "differences of value along v + e e_i");
  CheckAccumulator gradient("point_gradient", "differences of value along step(q, e E_i), E = tangent_basis(q)");
  CheckAccumulator velocity("velocity", "the inverse of momentum");
  std::vector<CheckAccumulator> blocks;
  for (const char* name : {"momentum_v", "momentum_q", "gradient_v", "gradient_q"}) {
    const bool of_momentum = name[0] == 'm', along_v = name[std::string_view(name).size() - 1] == 'v';
    blocks.emplace_back(std::string("hessian.") + name, std::string("differences of ") + (of_momentum ? "momentum" : "point_gradient") +
                                                            (along_v ? " along v + e e_i" : " along step(q, e E_i)"));
  }
  constexpr bool has_member = requires(const M& mf, const L& lg, double t, const manifolds::PointOf<M>& q,
                                        const manifolds::ComponentsOf<M>& v) {
    { lg.hessian(mf, t, q, v) } -> std::convertible_to<LagrangianHessian<M>>;
  };
  // An adapter whose hessian may difference (ErasedLagrangian) says whether it has its own.
  bool hessian = has_member;
  if constexpr (requires { { l.has_hessian() } -> std::convertible_to<bool>; }) hessian = l.has_hessian();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const std::string at = detail::describe<M>(samples[k]);
    const int index = static_cast<int>(k);
    detail::check_callbacks(manifold, l, samples[k], index, at, momentum, gradient, velocity);
    if constexpr (has_member) {
      if (hessian) detail::check_hessian(manifold, l, samples[k], index, at, blocks);
    }
  }
  mechanics::CheckReport report;
  report.samples = static_cast<int>(samples.size());
  for (const auto* acc : {&momentum, &gradient, &velocity}) report.checks.push_back(acc->result());
  if (hessian) {
    for (const auto& acc : blocks) report.checks.push_back(acc.result());
  } else {
    report.checks.push_back(mechanics::detail::no_analytic_hessian("point_gradient"));
  }
  return report;
}

}  // namespace cartan::general
