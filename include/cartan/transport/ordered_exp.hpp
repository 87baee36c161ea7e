#pragma once
// Ordered exponentials (the remark after the paper's Corollary "Parallel transport" (cor-parr)).
// Parallel transport built on them is in parallel_transport.hpp.
//
// Ordered exponential. For a generator A(t) (an n x n matrix, or an element of a Lie algebra)
//   Y(t) = Texp(int_s^t A(r) dr)  is the solution of  Y' = A(t) Y,  Y(s) = I
// (remark after cor-parr). It is approximated on the uniform grid t_k = s + k h, h = (t - s)/N,
// by Y_{k+1} = exp(Omega_k) Y_k with the Magnus exponent Omega_k of one step:
//   LieEuler  Omega = h A(t_k)                                       order 1  (disc-exp)
//   Magnus2   Omega = h A(t_k + h/2)                                 order 2  (midpoint)
//   Magnus4   Omega = h/2 (A1 + A2) + sqrt(3) h^2/12 [A2, A1],       order 4
//             A1,2 = A(t_k + (1/2 -+ sqrt(3)/6) h)  (two Gauss points)
// or, from samples A_k = A(t_k) at the nodes (and A_{k+1/2} = A(t_k + h/2) for Magnus4):
//   LieEuler  Omega = h A_k                                          order 1
//   Magnus2   Omega = h/2 (A_k + A_{k+1})                            order 2  (trapezoid)
//   Magnus4   Omega = h/6 (A_k + 4 A_{k+1/2} + A_{k+1}) + h^2/12 [A_{k+1}, A_k]   order 4 (Simpson)
// Both commutator terms equal -h^3/12 [a0, a1] + O(h^5) for A = a0 + a1 (r - t_mid) + ...,
// the second Magnus term. Every method is exact for a constant generator.
//
// Reversed intervals (t < s) use h < 0 and give Texp over [t, s] inverted: exactly (to rounding)
// for the symmetric methods Magnus2 and Magnus4, whose exponent changes sign with h, and to
// O(h) for LieEuler. t = s gives the identity.
//
// Entry points: `ordered_exp_nodes` returns Y at every node of the grid, `ordered_exp` only the
// last one (without storing the others). The generator is given either as a function of time
// with a number of steps, or as `Samples` (node values, and midpoint values for Magnus4).

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <string>
#include <string_view>
#include <type_traits>
#include <unsupported/Eigen/MatrixFunctions>
#include <utility>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"

namespace cartan::transport {

/// Integrators of the ordered exponential (see the header comment).
enum class TransportMethod { LieEuler, Magnus2, Magnus4 };

/// Convergence order of a method: 1, 2 or 4.
constexpr int order(TransportMethod method) {
  switch (method) {
    case TransportMethod::LieEuler:
      return 1;
    case TransportMethod::Magnus2:
      return 2;
    case TransportMethod::Magnus4:
      return 4;
  }
  return 0;
}

constexpr std::string_view to_string(TransportMethod method) {
  switch (method) {
    case TransportMethod::LieEuler:
      return "LieEuler";
    case TransportMethod::Magnus2:
      return "Magnus2";
    case TransportMethod::Magnus4:
      return "Magnus4";
  }
  return "unknown";
}

/// A function of time sampled on the uniform grid t_k = t0 + k h, h = (t1 - t0)/N, with
/// N = nodes.size() - 1 steps: nodes[k] at t_k, k = 0..N, and midpoints[k] at t_k + h/2,
/// k = 0..N-1. Magnus4 needs the midpoints; LieEuler and Magnus2 ignore them (but check them
/// when given). t1 < t0 (nodes in decreasing time) and t1 = t0 are allowed.
template <class X>
struct Samples {
  std::vector<X> nodes;
  std::vector<X> midpoints;  // empty, or N values
  double t0 = 0;
  double t1 = 1;
};
/// Samples{nodes, midpoints, t0, t1} deduces X (for compilers without aggregate deduction).
template <class X>
Samples(std::vector<X>, std::vector<X>, double, double) -> Samples<X>;

namespace detail {

inline constexpr double kSqrt3 = 1.7320508075688772935274463415059;
inline constexpr double kGaussOffset = kSqrt3 / 6;  // Gauss points at t_k + (1/2 -+ sqrt(3)/6) h

/// Generators that are n x n matrices: Y' = A Y in GL(n), [A, B] = AB - BA, step exp(Omega)
/// by Eigen's matrix exponential.
template <class M>
struct MatrixAlgebra {
  using Exponent = M;
  using Propagator = M;
  static Exponent commutator(const Exponent& a, const Exponent& b) { return a * b - b * a; }
  static Propagator step(const Exponent& omega) { return omega.exp(); }
  static Propagator compose(const Propagator& step, const Propagator& y) { return step * y; }
};

/// Generators in the Lie algebra of G: Y' = a Y in G (a = Y' Y^{-1}), [a, b] = ad_a b, step
/// exp(omega) by the group exponential.
template <groups::LieGroup G>
struct GroupAlgebra {
  using Exponent = groups::TangentOf<G>;
  using Propagator = groups::ElementOf<G>;
  static Exponent commutator(const Exponent& a, const Exponent& b) { return G::ad(a) * b; }
  static Propagator step(const Exponent& omega) { return G::exp(omega); }
  static Propagator compose(const Propagator& step, const Propagator& y) { return G::compose(step, y); }
};

/// The one stepping loop: Y_{k+1} = exp(Omega_k) Y_k, Y_0 = y0, for k = 0..steps-1. Stores
/// Y_0..Y_N in *nodes when nodes is not null; returns Y_N.
template <class Algebra, class StepExponent>
typename Algebra::Propagator propagate(int steps, typename Algebra::Propagator y, const StepExponent& exponent,
                                       std::vector<typename Algebra::Propagator>* nodes) {
  if (nodes != nullptr) {
    nodes->clear();
    nodes->reserve(static_cast<std::size_t>(steps) + 1);
    nodes->push_back(y);
  }
  for (int k = 0; k < steps; ++k) {
    y = Algebra::compose(Algebra::step(exponent(k)), y);
    if (nodes != nullptr) nodes->push_back(y);
  }
  return y;
}

/// Magnus exponent of step [t_k, t_k + h] from the generator as a function (header comment).
template <class Algebra, class F>
typename Algebra::Exponent function_step_exponent(TransportMethod method, const F& a, double tk, double h) {
  using X = typename Algebra::Exponent;
  switch (method) {
    case TransportMethod::LieEuler:
      return X(h * a(tk));
    case TransportMethod::Magnus2:
      return X(h * a(tk + 0.5 * h));
    case TransportMethod::Magnus4: {
      const X a1 = a(tk + (0.5 - kGaussOffset) * h);
      const X a2 = a(tk + (0.5 + kGaussOffset) * h);
      return X(0.5 * h * (a1 + a2) + (kSqrt3 / 12) * h * h * Algebra::commutator(a2, a1));
    }
  }
  return X(h * a(tk));  // unreachable
}

/// Magnus exponent of step k from samples (header comment).
template <class Algebra>
typename Algebra::Exponent sampled_step_exponent(TransportMethod method, const Samples<typename Algebra::Exponent>& a,
                                                 std::size_t k, double h) {
  using X = typename Algebra::Exponent;
  switch (method) {
    case TransportMethod::LieEuler:
      return X(h * a.nodes[k]);
    case TransportMethod::Magnus2:
      return X(0.5 * h * (a.nodes[k] + a.nodes[k + 1]));
    case TransportMethod::Magnus4:
      return X((h / 6) * (a.nodes[k] + 4 * a.midpoints[k] + a.nodes[k + 1]) +
               (h * h / 12) * Algebra::commutator(a.nodes[k + 1], a.nodes[k]));
  }
  return X(h * a.nodes[k]);  // unreachable
}

inline void check_interval(std::string_view where, double t0, double t1) {
  require_finite(t0, where, "t0");
  require_finite(t1, where, "t1");
}

inline void check_steps(std::string_view where, int steps) {
  if (steps < 1) throw_invalid(where, "steps", std::to_string(steps), "must be at least 1");
}

/// Wraps a function of time (a generator A, or a velocity u) so that each value is checked
/// (finite, and of the given shape; messages name it "<name>(t)") and converted to X.
template <class X, class F>
auto checked_function(std::string_view where, std::string_view name, F f, Eigen::Index rows, Eigen::Index cols) {
  return [where, name, f = std::move(f), rows, cols](double t) -> X {
    X value = f(t);
    if (value.rows() != rows || value.cols() != cols || !value.allFinite()) {
      const std::string label = std::string(name) + "(" + format_value(t) + ")";
      require_shape(value, rows, cols, where, label);
      require_finite(value, where, label);
    }
    return value;
  };
}

/// Checks sample counts, shapes and finiteness; messages name the samples `<prefix>nodes[k]`
/// and `<prefix>midpoints[k]`. `square` requires n x n samples.
template <class X>
void check_samples(std::string_view where, std::string_view prefix, const Samples<X>& a, TransportMethod method,
                   bool square) {
  check_interval(where, a.t0, a.t1);
  const std::string nodes_name = std::string(prefix) + "nodes", mids_name = std::string(prefix) + "midpoints";
  if (a.nodes.size() < 2) {
    throw_invalid(where, nodes_name + ".size()", std::to_string(a.nodes.size()),
                  "must be at least 2 (samples at t_0..t_N, N >= 1)");
  }
  if (method == TransportMethod::Magnus4 && a.midpoints.empty()) {
    throw_invalid(where, "method", std::string(to_string(method)),
                  "needs midpoint samples A(t_k + h/2): pass them, or use Magnus2 (trapezoid)");
  }
  if (!a.midpoints.empty() && a.midpoints.size() + 1 != a.nodes.size()) {
    throw_invalid(where, mids_name + ".size()", std::to_string(a.midpoints.size()),
                  "must be " + nodes_name + ".size() - 1 = " + std::to_string(a.nodes.size() - 1));
  }
  const Eigen::Index rows = a.nodes[0].rows(), cols = a.nodes[0].cols();
  if (square && rows != cols) {
    throw_invalid(where, nodes_name + "[0]", format_value(a.nodes[0]),
                  "is not square (" + std::to_string(rows) + "x" + std::to_string(cols) + ")");
  }
  auto check = [&](const std::vector<X>& samples, const std::string& name) {
    for (std::size_t k = 0; k < samples.size(); ++k) {
      if (samples[k].rows() == rows && samples[k].cols() == cols && samples[k].allFinite()) continue;
      const std::string label = name + "[" + std::to_string(k) + "]";
      require_shape(samples[k], rows, cols, where, label);
      require_finite(samples[k], where, label);
    }
  };
  check(a.nodes, nodes_name);
  check(a.midpoints, mids_name);
}

/// The same samples mapped through f (generator samples from velocity samples, say).
template <class X, class F>
auto map_samples(const Samples<X>& a, const F& f) {
  using Y = std::decay_t<std::invoke_result_t<const F&, const X&>>;
  Samples<Y> out{{}, {}, a.t0, a.t1};
  out.nodes.reserve(a.nodes.size());
  out.midpoints.reserve(a.midpoints.size());
  for (const X& x : a.nodes) out.nodes.push_back(f(x));
  for (const X& x : a.midpoints) out.midpoints.push_back(f(x));
  return out;
}

template <class F>
using GeneratorMatrix = typename std::decay_t<std::invoke_result_t<const F&, double>>::PlainObject;

/// Ordered exponential of a generator function (algebra elements for Algebra = GroupAlgebra<G>,
/// checked matrices otherwise) from y0: Y_N, and Y_0..Y_N in *nodes if given.
template <class Algebra, class F>
typename Algebra::Propagator propagate_function(std::string_view where, const F& a, double t0, double t1, int steps,
                                                TransportMethod method, typename Algebra::Propagator y0,
                                                std::vector<typename Algebra::Propagator>* nodes) {
  check_interval(where, t0, t1);
  check_steps(where, steps);
  const double h = (t1 - t0) / steps;
  auto exponent = [&](int k) {
    const double tk = t0 + (t1 - t0) * (static_cast<double>(k) / steps);
    return function_step_exponent<Algebra>(method, a, tk, h);
  };
  return propagate<Algebra>(steps, std::move(y0), exponent, nodes);
}

/// Ordered exponential of samples from y0 (samples checked first; `square` for matrices).
template <class Algebra>
typename Algebra::Propagator propagate_samples(std::string_view where, const Samples<typename Algebra::Exponent>& a,
                                               TransportMethod method, typename Algebra::Propagator y0,
                                               std::vector<typename Algebra::Propagator>* nodes, bool square) {
  check_samples(where, "", a, method, square);
  const int steps = static_cast<int>(a.nodes.size() - 1);
  const double h = (a.t1 - a.t0) / steps;
  auto exponent = [&](int k) { return sampled_step_exponent<Algebra>(method, a, static_cast<std::size_t>(k), h); };
  return propagate<Algebra>(steps, std::move(y0), exponent, nodes);
}

/// Texp of a matrix generator function, checked (square, finite, of one size; named "A(t)").
template <class F>
GeneratorMatrix<F> matrix_function(std::string_view where, const F& a, double t0, double t1, int steps,
                                   TransportMethod method, std::vector<GeneratorMatrix<F>>* nodes) {
  using M = GeneratorMatrix<F>;
  check_interval(where, t0, t1);
  check_steps(where, steps);
  const M first = a(t0);
  if (first.rows() != first.cols()) {
    throw_invalid(where, "A(" + format_value(t0) + ")", format_value(first),
                  "is not square (" + std::to_string(first.rows()) + "x" + std::to_string(first.cols()) + ")");
  }
  const auto checked = checked_function<M>(where, "A", std::cref(a), first.rows(), first.cols());
  return propagate_function<MatrixAlgebra<M>>(where, checked, t0, t1, steps, method,
                                              M::Identity(first.rows(), first.cols()), nodes);
}

/// Texp of matrix samples (the identity of their size; the checks reject empty samples).
template <class M>
M matrix_samples(std::string_view where, const Samples<M>& a, TransportMethod method,
                 std::type_identity_t<std::vector<M>>* nodes) {
  M identity;
  if (!a.nodes.empty()) {
    identity = M::Identity(a.nodes[0].rows(), a.nodes[0].cols());
  } else if constexpr (M::SizeAtCompileTime != Eigen::Dynamic) {
    identity = M::Zero();
  }
  return propagate_samples<MatrixAlgebra<M>>(where, a, method, std::move(identity), nodes, true);
}

}  // namespace detail

// ------------------------------------------------------------------------------------------
// Ordered exponential of a matrix generator (remark after cor-parr)

/// Y(t_0), ..., Y(t_N) at the nodes t_k = t0 + k (t1 - t0)/steps (Y(t_0) = I) for a function A(t)
/// returning an n x n Eigen matrix, with `steps` uniform steps of `method`. t1 < t0 integrates
/// backwards; t1 = t0 gives I. Throws std::invalid_argument for steps < 1, non-finite t0/t1, or a
/// non-square or non-finite A(t) (naming the value).
template <class F>
std::vector<detail::GeneratorMatrix<F>> ordered_exp_nodes(const F& a, double t0, double t1, int steps,
                                                          TransportMethod method) {
  std::vector<detail::GeneratorMatrix<F>> out;
  detail::matrix_function("ordered_exp_nodes", a, t0, t1, steps, method, &out);
  return out;
}

/// Y(t1) = Texp(int_{t0}^{t1} A(r) dr): the last node of ordered_exp_nodes.
template <class F>
detail::GeneratorMatrix<F> ordered_exp(const F& a, double t0, double t1, int steps, TransportMethod method) {
  return detail::matrix_function("ordered_exp", a, t0, t1, steps, method, nullptr);
}

/// Y(t_0), ..., Y(t_N) from samples of A (Samples; Magnus2 is the trapezoid rule, Magnus4
/// Simpson's rule + h^2/12 [A_{k+1}, A_k] and needs midpoints). Throws std::invalid_argument for
/// fewer than 2 samples, missing or miscounted midpoints, non-finite, non-square or differently
/// sized samples.
template <class M>
std::vector<M> ordered_exp_nodes(const Samples<M>& a, TransportMethod method) {
  std::vector<M> out;
  detail::matrix_samples("ordered_exp_nodes", a, method, &out);
  return out;
}

/// Y(t_N) from samples: the last node of ordered_exp_nodes.
template <class M>
M ordered_exp(const Samples<M>& a, TransportMethod method) {
  return detail::matrix_samples("ordered_exp", a, method, nullptr);
}

}  // namespace cartan::transport
