#pragma once
// Ordered exponentials and parallel transport along curves (paper §3 Corollary "Parallel
// transport" (cor-parr) and the remark after it; §5 (parr-tran-Cartan-lambda), Remark rem-simple;
// §7 (disc-exp); appendix H3 (para-trans-Heis), (para-trans-dual-Heis)).
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
// Parallel transport (cor-parr). For an InvariantConnection and a curve g(.) whose velocity,
// trivialised on the connection's side, is u(t) (left: the body velocity g^{-1} g'; right:
// g' g^{-1}), the trivialised transport operator is
//   P(s -> t) = Texp(-int_s^t nabla_{u(r)} dr)  (generator InvariantConnection::transport_generator),
//   Gamma(g)_s^t X = translate(g(t), P trivialise(g(s), X))                      (eq:parr-left)
// (the right version, appendix "Right formalism", uses right translations). Covectors:
//   Gamma*(g)_s^t = (Gamma(g)_s^t)^{-*}: trivialised P^{-T}, so <Gamma* a, Gamma X> = <a, X>
//     (eq:parr-left-dual: Texp(+int nabla*_u) = P^{-T});
//   Gamma*(g)_t^s = (Gamma(g)_s^t)^*: the pull-back to the start, trivialised P^T. This is the
//     eta = Gamma*(g)_t^0 dl/dg of the reduced equations (docs/paper-notes.md#convention-dual-transport).
//
// Cartan–Schouten fast path. For the CS connection the generator is -c ad_u with c = lambda
// (left, CS-conn) or lambda - 1 (right, CS-conn-right). ad is a Lie algebra homomorphism
// ([ad_a, ad_b] = ad_[a,b]), so every Magnus exponent above is ad_omega for an omega in the
// algebra, and exp(ad_omega) = Ad_{exp(omega)}: the transport is P = Ad(Y) where Y in G solves
// Y' = (-c u) Y, computed with the same steps in the algebra (no matrix exponential).

#include <Eigen/Dense>
#include <array>
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
#include "cartan/connections/invariant_connection.hpp"
#include "cartan/groups/side.hpp"

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

/// Magnus exponent of step k from node samples (and midpoint samples for Magnus4).
template <class Algebra>
typename Algebra::Exponent sampled_step_exponent(TransportMethod method,
                                                 const std::vector<typename Algebra::Exponent>& nodes,
                                                 const std::vector<typename Algebra::Exponent>& midpoints,
                                                 std::size_t k, double h) {
  using X = typename Algebra::Exponent;
  switch (method) {
    case TransportMethod::LieEuler:
      return X(h * nodes[k]);
    case TransportMethod::Magnus2:
      return X(0.5 * h * (nodes[k] + nodes[k + 1]));
    case TransportMethod::Magnus4:
      return X((h / 6) * (nodes[k] + 4 * midpoints[k] + nodes[k + 1]) +
               (h * h / 12) * Algebra::commutator(nodes[k + 1], nodes[k]));
  }
  return X(h * nodes[k]);  // unreachable
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
void check_samples(std::string_view where, std::string_view prefix, const std::vector<X>& nodes,
                   const std::vector<X>* midpoints, TransportMethod method, bool square) {
  const std::string nodes_name = std::string(prefix) + "nodes", mids_name = std::string(prefix) + "midpoints";
  if (nodes.size() < 2) {
    throw_invalid(where, nodes_name + ".size()", std::to_string(nodes.size()),
                  "must be at least 2 (samples at t_0..t_N, N >= 1)");
  }
  if (method == TransportMethod::Magnus4 && midpoints == nullptr) {
    throw_invalid(where, "method", std::string(to_string(method)),
                  "needs midpoint samples A(t_k + h/2): pass them, or use Magnus2 (trapezoid)");
  }
  if (midpoints != nullptr && midpoints->size() + 1 != nodes.size()) {
    throw_invalid(where, mids_name + ".size()", std::to_string(midpoints->size()),
                  "must be " + nodes_name + ".size() - 1 = " + std::to_string(nodes.size() - 1));
  }
  const Eigen::Index rows = nodes[0].rows(), cols = nodes[0].cols();
  if (square && rows != cols) {
    throw_invalid(where, nodes_name + "[0]", format_value(nodes[0]),
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
  check(nodes, nodes_name);
  if (midpoints != nullptr) check(*midpoints, mids_name);
}

template <class F>
using GeneratorMatrix = typename std::decay_t<std::invoke_result_t<const F&, double>>::PlainObject;

/// Ordered exponential of a matrix generator function; Y_N, and Y_0..Y_N in *nodes if given.
template <class F>
GeneratorMatrix<F> ordered_exp_function(std::string_view where, const F& a, double t0, double t1, int steps,
                                        TransportMethod method, std::vector<GeneratorMatrix<F>>* nodes) {
  using M = GeneratorMatrix<F>;
  check_interval(where, t0, t1);
  check_steps(where, steps);
  const M first = a(t0);
  if (first.rows() != first.cols()) {
    throw_invalid(where, "A(" + format_value(t0) + ")", format_value(first),
                  "is not square (" + std::to_string(first.rows()) + "x" + std::to_string(first.cols()) + ")");
  }
  const auto checked = checked_function<M>(where, "A", a, first.rows(), first.cols());
  const double h = (t1 - t0) / steps;
  auto exponent = [&](int k) {
    const double tk = t0 + (t1 - t0) * (static_cast<double>(k) / steps);
    return function_step_exponent<MatrixAlgebra<M>>(method, checked, tk, h);
  };
  return propagate<MatrixAlgebra<M>>(steps, M::Identity(first.rows(), first.cols()), exponent, nodes);
}

/// Ordered exponential of a sampled generator (matrices, or algebra elements for Algebra =
/// GroupAlgebra<G>); y0 is the identity propagator.
template <class Algebra>
typename Algebra::Propagator ordered_exp_samples(std::string_view where,
                                                 const std::vector<typename Algebra::Exponent>& nodes,
                                                 const std::vector<typename Algebra::Exponent>* midpoints, double t0,
                                                 double t1, TransportMethod method, typename Algebra::Propagator y0,
                                                 std::vector<typename Algebra::Propagator>* out, bool square) {
  check_interval(where, t0, t1);
  check_samples(where, "", nodes, midpoints, method, square);
  static const std::vector<typename Algebra::Exponent> kNone;
  const auto& mids = midpoints != nullptr ? *midpoints : kNone;
  const int steps = static_cast<int>(nodes.size() - 1);
  const double h = (t1 - t0) / steps;
  auto exponent = [&](int k) {
    return sampled_step_exponent<Algebra>(method, nodes, mids, static_cast<std::size_t>(k), h);
  };
  return propagate<Algebra>(steps, std::move(y0), exponent, out);
}

/// The identity of the samples' size (a placeholder when there are none: the checks reject that).
template <class M>
M matrix_identity_like(const std::vector<M>& nodes) {
  if (!nodes.empty()) return M::Identity(nodes[0].rows(), nodes[0].cols());
  if constexpr (M::SizeAtCompileTime == Eigen::Dynamic) {
    return M();
  } else {
    return M::Zero();
  }
}

}  // namespace detail

// ------------------------------------------------------------------------------------------
// Ordered exponential of a matrix generator (remark after cor-parr)

/// Y(t1) = Texp(int_{t0}^{t1} A(r) dr) for a function A(t) returning an n x n Eigen matrix,
/// with `steps` uniform steps of `method`. t1 < t0 integrates backwards; t1 = t0 gives I.
/// Throws std::invalid_argument for steps < 1, non-finite t0/t1, or a non-square or
/// non-finite A(t) (naming the value).
template <class F>
detail::GeneratorMatrix<F> ordered_exp(const F& a, double t0, double t1, int steps, TransportMethod method) {
  return detail::ordered_exp_function("ordered_exp", a, t0, t1, steps, method, nullptr);
}

/// Y(t_0), ..., Y(t_N) at the grid nodes t_k = t0 + k (t1 - t0)/steps (Y(t_0) = I).
template <class F>
std::vector<detail::GeneratorMatrix<F>> ordered_exp_nodes(const F& a, double t0, double t1, int steps,
                                                          TransportMethod method) {
  std::vector<detail::GeneratorMatrix<F>> out;
  detail::ordered_exp_function("ordered_exp_nodes", a, t0, t1, steps, method, &out);
  return out;
}

/// Y(t_N) from samples nodes[k] = A(t_k) at t_k = t0 + k (t1 - t0)/N, N = nodes.size() - 1:
/// LieEuler (left point) or Magnus2 (trapezoid). Magnus4 needs midpoint samples (overload
/// below) and is rejected here with std::invalid_argument, as are fewer than 2 samples and
/// non-finite, non-square or differently sized samples. t1 < t0 (nodes in decreasing time) and
/// t1 = t0 are allowed as for ordered_exp.
template <class M>
M ordered_exp_sampled(const std::vector<M>& nodes, double t0, double t1, TransportMethod method) {
  return detail::ordered_exp_samples<detail::MatrixAlgebra<M>>("ordered_exp_sampled", nodes, nullptr, t0, t1, method,
                                                               detail::matrix_identity_like(nodes), nullptr, true);
}

/// As above with midpoint samples midpoints[k] = A(t_k + h/2), k = 0..N-1, which Magnus4 uses
/// (Simpson's rule + h^2/12 [A_{k+1}, A_k]); LieEuler and Magnus2 ignore them.
template <class M>
M ordered_exp_sampled(const std::vector<M>& nodes, const std::vector<M>& midpoints, double t0, double t1,
                      TransportMethod method) {
  return detail::ordered_exp_samples<detail::MatrixAlgebra<M>>("ordered_exp_sampled", nodes, &midpoints, t0, t1, method,
                                                               detail::matrix_identity_like(nodes), nullptr, true);
}

/// Y(t_0), ..., Y(t_N) from samples (see ordered_exp_sampled).
template <class M>
std::vector<M> ordered_exp_sampled_nodes(const std::vector<M>& nodes, double t0, double t1, TransportMethod method) {
  std::vector<M> out;
  detail::ordered_exp_samples<detail::MatrixAlgebra<M>>("ordered_exp_sampled_nodes", nodes, nullptr, t0, t1, method,
                                                        detail::matrix_identity_like(nodes), &out, true);
  return out;
}

template <class M>
std::vector<M> ordered_exp_sampled_nodes(const std::vector<M>& nodes, const std::vector<M>& midpoints, double t0,
                                         double t1, TransportMethod method) {
  std::vector<M> out;
  detail::ordered_exp_samples<detail::MatrixAlgebra<M>>("ordered_exp_sampled_nodes", nodes, &midpoints, t0, t1, method,
                                                        detail::matrix_identity_like(nodes), &out, true);
  return out;
}

// ------------------------------------------------------------------------------------------
// Trivialised parallel transport of an invariant connection (cor-parr)

namespace detail {

/// The generator -nabla_{u(t)} as a function of time, with u(t) checked (named "u(t)").
template <groups::LieGroup G, class U>
auto connection_generator(std::string_view where, const connections::InvariantConnection<G>& connection, const U& u) {
  return [&connection, u_checked = checked_function<groups::TangentOf<G>>(where, "u", std::cref(u), G::kDim, 1)](double t) {
    return groups::AlgebraMatrixOf<G>(connection.transport_generator(u_checked(t)));
  };
}

/// P(s -> t) (and the node values in *out) from velocity samples: the samples are checked (named
/// u_nodes, u_midpoints), then mapped to generator samples -nabla_u (linear in u).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> transport_sampled(std::string_view where, const connections::InvariantConnection<G>& connection,
                                     const std::vector<groups::TangentOf<G>>& u_nodes,
                                     const std::vector<groups::TangentOf<G>>* u_midpoints, double s, double t,
                                     TransportMethod method, std::vector<groups::AlgebraMatrixOf<G>>* out) {
  check_samples(where, "u_", u_nodes, u_midpoints, method, false);
  auto generators = [&connection](const std::vector<groups::TangentOf<G>>& u) {
    std::vector<groups::AlgebraMatrixOf<G>> a;
    a.reserve(u.size());
    for (const auto& x : u) a.push_back(connection.transport_generator(x));
    return a;
  };
  const auto mids = u_midpoints != nullptr ? generators(*u_midpoints) : std::vector<groups::AlgebraMatrixOf<G>>{};
  return ordered_exp_samples<MatrixAlgebra<groups::AlgebraMatrixOf<G>>>(where, generators(u_nodes),
                                                                u_midpoints != nullptr ? &mids : nullptr, s, t, method,
                                                                groups::AlgebraMatrixOf<G>::Identity(), out, true);
}

}  // namespace detail

/// P(s -> t) = Texp(-int_s^t nabla_{u(r)} dr) (cor-parr) for a curve whose velocity trivialised on
/// the connection's side is u(r) (a function returning G::Tangent): left connections take the
/// body velocity g^{-1} g', right ones g' g^{-1}. Validation as for ordered_exp.
template <groups::LieGroup G, class U>
groups::AlgebraMatrixOf<G> transport_operator(const connections::InvariantConnection<G>& connection, const U& u, double s, double t,
                                      int steps, TransportMethod method) {
  return detail::ordered_exp_function("transport_operator",
                                      detail::connection_generator("transport_operator", connection, u), s, t, steps,
                                      method, nullptr);
}

/// P(s -> t_k) at the grid nodes t_k = s + k (t - s)/steps, k = 0..steps.
template <groups::LieGroup G, class U>
std::vector<groups::AlgebraMatrixOf<G>> transport_operator_nodes(const connections::InvariantConnection<G>& connection, const U& u, double s,
                                                         double t, int steps, TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::ordered_exp_function("transport_operator_nodes",
                               detail::connection_generator("transport_operator_nodes", connection, u), s, t, steps,
                               method, &out);
  return out;
}

/// P(s -> t) from velocity samples u_nodes[k] = u(t_k), t_k = s + k (t - s)/N: LieEuler or
/// Magnus2 (as ordered_exp_sampled).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> transport_operator_sampled(const connections::InvariantConnection<G>& connection,
                                              const std::vector<groups::TangentOf<G>>& u_nodes, double s, double t,
                                              TransportMethod method) {
  return detail::transport_sampled("transport_operator_sampled", connection, u_nodes, nullptr, s, t, method, nullptr);
}

/// As above with midpoint samples u_midpoints[k] = u(t_k + h/2), needed by Magnus4.
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> transport_operator_sampled(const connections::InvariantConnection<G>& connection,
                                              const std::vector<groups::TangentOf<G>>& u_nodes,
                                              const std::vector<groups::TangentOf<G>>& u_midpoints, double s, double t,
                                              TransportMethod method) {
  return detail::transport_sampled("transport_operator_sampled", connection, u_nodes, &u_midpoints, s, t, method,
                                   nullptr);
}

/// P(s -> t_k) at every node from velocity samples.
template <groups::LieGroup G>
std::vector<groups::AlgebraMatrixOf<G>> transport_operator_sampled_nodes(const connections::InvariantConnection<G>& connection,
                                                                 const std::vector<groups::TangentOf<G>>& u_nodes, double s,
                                                                 double t, TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::transport_sampled("transport_operator_sampled_nodes", connection, u_nodes, nullptr, s, t, method, &out);
  return out;
}

template <groups::LieGroup G>
std::vector<groups::AlgebraMatrixOf<G>> transport_operator_sampled_nodes(const connections::InvariantConnection<G>& connection,
                                                                 const std::vector<groups::TangentOf<G>>& u_nodes,
                                                                 const std::vector<groups::TangentOf<G>>& u_midpoints, double s,
                                                                 double t, TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::transport_sampled("transport_operator_sampled_nodes", connection, u_nodes, &u_midpoints, s, t, method, &out);
  return out;
}

// ------------------------------------------------------------------------------------------
// Cartan–Schouten fast path (parr-tran-Cartan-lambda, disc-exp)

/// One Lie–Euler step of the left CS transport, exp(-lambda h ad_u) = Ad_{exp(-lambda h u)}
/// (disc-exp: P_{k+1} = exp(-lambda h ad_{u_k}) P_k). For the right description pass lambda - 1.
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> cartan_schouten_transport_step(double lambda, double h, const groups::TangentOf<G>& u) {
  return G::Ad(G::exp(groups::TangentOf<G>(-lambda * h * u)));
}

namespace detail {

/// The coefficient c of the CS generator -c ad_u: lambda (left, CS-conn), lambda - 1 (right,
/// CS-conn-right).
inline double cartan_schouten_coefficient(std::string_view where, double lambda, groups::Side side) {
  require_finite(lambda, where, "lambda");
  return side == groups::Side::Left ? lambda : lambda - 1;
}

/// P = Ad(Y) at the last node (and at every node in *out), where Y' = -c u Y in G is integrated
/// with the algebra-valued Magnus steps (GroupAlgebra) from u as a function.
template <groups::LieGroup G, class U>
groups::AlgebraMatrixOf<G> cartan_schouten_function(std::string_view where, double lambda, groups::Side side, const U& u, double s,
                                            double t, int steps, TransportMethod method,
                                            std::vector<groups::AlgebraMatrixOf<G>>* out) {
  const double c = cartan_schouten_coefficient(where, lambda, side);
  check_interval(where, s, t);
  check_steps(where, steps);
  const auto checked = checked_function<groups::TangentOf<G>>(where, "u", std::cref(u), G::kDim, 1);
  auto generator = [&checked, c](double r) { return groups::TangentOf<G>(-c * checked(r)); };
  const double h = (t - s) / steps;
  auto exponent = [&](int k) {
    const double tk = s + (t - s) * (static_cast<double>(k) / steps);
    return function_step_exponent<GroupAlgebra<G>>(method, generator, tk, h);
  };
  std::vector<groups::ElementOf<G>> ys;
  const groups::ElementOf<G> y = propagate<GroupAlgebra<G>>(steps, G::identity(), exponent, out != nullptr ? &ys : nullptr);
  if (out != nullptr) {
    out->clear();
    for (const auto& yk : ys) out->push_back(G::Ad(yk));
  }
  return G::Ad(y);
}

/// As above from velocity samples (checked and named u_nodes, u_midpoints).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> cartan_schouten_sampled(std::string_view where, double lambda, groups::Side side,
                                           const std::vector<groups::TangentOf<G>>& u_nodes,
                                           const std::vector<groups::TangentOf<G>>* u_midpoints, double s, double t,
                                           TransportMethod method, std::vector<groups::AlgebraMatrixOf<G>>* out) {
  const double c = cartan_schouten_coefficient(where, lambda, side);
  check_samples(where, "u_", u_nodes, u_midpoints, method, false);
  auto generators = [c](const std::vector<groups::TangentOf<G>>& u) {
    std::vector<groups::TangentOf<G>> a;
    a.reserve(u.size());
    for (const auto& x : u) a.push_back(-c * x);
    return a;
  };
  const auto mids = u_midpoints != nullptr ? generators(*u_midpoints) : std::vector<groups::TangentOf<G>>{};
  std::vector<groups::ElementOf<G>> ys;
  const groups::ElementOf<G> y =
      ordered_exp_samples<GroupAlgebra<G>>(where, generators(u_nodes), u_midpoints != nullptr ? &mids : nullptr, s, t,
                                           method, G::identity(), out != nullptr ? &ys : nullptr, false);
  if (out != nullptr) {
    out->clear();
    for (const auto& yk : ys) out->push_back(G::Ad(yk));
  }
  return G::Ad(y);
}

}  // namespace detail

/// P(s -> t) of the Cartan–Schouten connection of parameter lambda (parr-tran-Cartan-lambda),
/// for the velocity u trivialised on `side` (left: body velocity; right: g' g^{-1}), computed in
/// the algebra: P = Ad(Y), Y' = -c u Y in G (c = lambda left, lambda - 1 right). Agrees with
/// transport_operator(cartan_schouten<G>(lambda, side), ...) to rounding, for every method.
template <groups::LieGroup G, class U>
groups::AlgebraMatrixOf<G> cartan_schouten_transport(double lambda, groups::Side side, const U& u, double s, double t, int steps,
                                             TransportMethod method) {
  return detail::cartan_schouten_function<G>("cartan_schouten_transport", lambda, side, u, s, t, steps, method,
                                             nullptr);
}

/// P(s -> t_k) at the grid nodes, k = 0..steps.
template <groups::LieGroup G, class U>
std::vector<groups::AlgebraMatrixOf<G>> cartan_schouten_transport_nodes(double lambda, groups::Side side, const U& u, double s,
                                                                double t, int steps, TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::cartan_schouten_function<G>("cartan_schouten_transport_nodes", lambda, side, u, s, t, steps, method, &out);
  return out;
}

/// From velocity samples u(t_k) (LieEuler, Magnus2), as transport_operator_sampled.
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> cartan_schouten_transport_sampled(double lambda, groups::Side side, const std::vector<groups::TangentOf<G>>& u_nodes,
                                                     double s, double t, TransportMethod method) {
  return detail::cartan_schouten_sampled<G>("cartan_schouten_transport_sampled", lambda, side, u_nodes, nullptr, s, t,
                                            method, nullptr);
}

/// From node and midpoint samples (all methods).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> cartan_schouten_transport_sampled(double lambda, groups::Side side, const std::vector<groups::TangentOf<G>>& u_nodes,
                                                     const std::vector<groups::TangentOf<G>>& u_midpoints, double s, double t,
                                                     TransportMethod method) {
  return detail::cartan_schouten_sampled<G>("cartan_schouten_transport_sampled", lambda, side, u_nodes, &u_midpoints, s,
                                            t, method, nullptr);
}

/// P(s -> t_k) at every node from samples.
template <groups::LieGroup G>
std::vector<groups::AlgebraMatrixOf<G>> cartan_schouten_transport_sampled_nodes(double lambda, groups::Side side,
                                                                        const std::vector<groups::TangentOf<G>>& u_nodes,
                                                                        double s, double t, TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::cartan_schouten_sampled<G>("cartan_schouten_transport_sampled_nodes", lambda, side, u_nodes, nullptr, s, t,
                                     method, &out);
  return out;
}

template <groups::LieGroup G>
std::vector<groups::AlgebraMatrixOf<G>> cartan_schouten_transport_sampled_nodes(double lambda, groups::Side side,
                                                                        const std::vector<groups::TangentOf<G>>& u_nodes,
                                                                        const std::vector<groups::TangentOf<G>>& u_midpoints,
                                                                        double s, double t, TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::cartan_schouten_sampled<G>("cartan_schouten_transport_sampled_nodes", lambda, side, u_nodes, &u_midpoints, s,
                                     t, method, &out);
  return out;
}

// ------------------------------------------------------------------------------------------
// Applying a transport operator

/// Gamma_s^t in trivialised form: x -> P x.
template <class Mat, class Vec>
typename Vec::PlainObject transport_vector(const Eigen::MatrixBase<Mat>& p, const Eigen::MatrixBase<Vec>& x) {
  return p * x;
}

/// Gamma*(g)_s^t in trivialised form (eq:parr-left-dual): alpha -> P^{-T} alpha, so that
/// <P^{-T} alpha, P x> = <alpha, x>.
template <class Mat, class Vec>
typename Vec::PlainObject transport_covector(const Eigen::MatrixBase<Mat>& p, const Eigen::MatrixBase<Vec>& alpha) {
  return p.transpose().partialPivLu().solve(alpha);
}

/// Gamma*(g)_t^s = (Gamma(g)_s^t)^* in trivialised form: alpha -> P^T alpha, pulling a covector
/// at g(t) back to g(s) (docs/paper-notes.md#convention-dual-transport: eta = P^T zeta; para-trans-dual-Heis).
template <class Mat, class Vec>
typename Vec::PlainObject pull_back_covector(const Eigen::MatrixBase<Mat>& p, const Eigen::MatrixBase<Vec>& alpha) {
  return p.transpose() * alpha;
}

namespace detail {
template <groups::LieGroup G>
void check_transport_points(std::string_view where, const groups::AlgebraMatrixOf<G>& p, const groups::ElementOf<G>& g_s,
                            const groups::ElementOf<G>& g_t) {
  require_finite(p, where, "P");
  G::validate(g_s, "g_s");
  G::validate(g_t, "g_t");
}
}  // namespace detail

/// Gamma(g)_s^t X = translate(g(t), P trivialise(g(s), X)) (eq:parr-left; right-translated for
/// a right connection), for a tangent vector X at g_s = g(s) in ambient coordinates, with
/// P = P(s -> t) of a connection on `side`.
template <groups::LieGroup G>
groups::ElementOf<G> transport_tangent(groups::Side side, const groups::AlgebraMatrixOf<G>& p, const groups::ElementOf<G>& g_s, const groups::ElementOf<G>& g_t,
                               const groups::ElementOf<G>& x) {
  detail::check_transport_points<G>("transport_tangent", p, g_s, g_t);
  require_finite(x, "transport_tangent", "X");
  return groups::translate<G>(side, g_t, groups::TangentOf<G>(p * groups::trivialise<G>(side, g_s, x)));
}

/// Gamma*(g)_s^t alpha (eq:parr-left-dual) for an ambient covector alpha at g(s): the covector
/// at g(t) (tangent to G, see untrivialise_covector) with trivialisation P^{-T} trivialise(alpha).
template <groups::LieGroup G>
groups::ElementOf<G> transport_ambient_covector(groups::Side side, const groups::AlgebraMatrixOf<G>& p, const groups::ElementOf<G>& g_s,
                                        const groups::ElementOf<G>& g_t, const groups::ElementOf<G>& alpha) {
  detail::check_transport_points<G>("transport_ambient_covector", p, g_s, g_t);
  require_finite(alpha, "transport_ambient_covector", "alpha");
  return groups::untrivialise_covector<G>(side, g_t, transport_covector(p, groups::trivialise_covector<G>(side, g_s, alpha)));
}

/// Gamma*(g)_t^s alpha = (Gamma(g)_s^t)^* alpha for an ambient covector alpha at g(t): the
/// covector at g(s) with trivialisation P^T trivialise(alpha) (para-trans-dual-Heis on H3).
template <groups::LieGroup G>
groups::ElementOf<G> pull_back_ambient_covector(groups::Side side, const groups::AlgebraMatrixOf<G>& p, const groups::ElementOf<G>& g_s,
                                        const groups::ElementOf<G>& g_t, const groups::ElementOf<G>& alpha) {
  detail::check_transport_points<G>("pull_back_ambient_covector", p, g_s, g_t);
  require_finite(alpha, "pull_back_ambient_covector", "alpha");
  return groups::untrivialise_covector<G>(side, g_s, pull_back_covector(p, groups::trivialise_covector<G>(side, g_t, alpha)));
}

}  // namespace cartan::transport
