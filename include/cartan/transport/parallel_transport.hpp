#pragma once
// Parallel transport of invariant connections along curves in a Lie group (paper §3 Corollary
// "Parallel transport" (cor-parr); §5 (parr-tran-Cartan-lambda), Remark rem-simple; appendix H3
// (para-trans-Heis), (para-trans-dual-Heis)), as ordered exponentials (ordered_exp.hpp).
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

//
// Entry points, as for ordered_exp: `*_nodes` returns P(s -> t_k) at every node, the name without
// `_nodes` the last one; the velocity is a function of time with a number of steps, or Samples.

#include <Eigen/Dense>
#include <functional>
#include <string_view>
#include <vector>

#include "cartan/connections/invariant_connection.hpp"
#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/groups/side.hpp"
#include "cartan/transport/ordered_exp.hpp"

namespace cartan::transport {

// ------------------------------------------------------------------------------------------
// Trivialised parallel transport of an invariant connection (cor-parr)

namespace detail {

/// P(s -> t) (and the node values in *out) for a velocity function, checked and named "u(t)".
template <groups::LieGroup G, class U>
groups::AlgebraMatrixOf<G> connection_function(std::string_view where, const connections::InvariantConnection<G>& connection,
                                               const U& u, double s, double t, int steps, TransportMethod method,
                                               std::vector<groups::AlgebraMatrixOf<G>>* out) {
  const auto u_checked = checked_function<groups::TangentOf<G>>(where, "u", std::cref(u), G::kDim, 1);
  auto generator = [&](double r) { return groups::AlgebraMatrixOf<G>(connection.transport_generator(u_checked(r))); };
  return propagate_function<MatrixAlgebra<groups::AlgebraMatrixOf<G>>>(where, generator, s, t, steps, method,
                                                                      groups::AlgebraMatrixOf<G>::Identity(), out);
}

/// P(s -> t) from velocity samples: checked (named u_nodes, u_midpoints), then mapped to
/// generator samples -nabla_u (linear in u).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> connection_samples(std::string_view where, const connections::InvariantConnection<G>& connection,
                                              const Samples<groups::TangentOf<G>>& u, TransportMethod method,
                                              std::vector<groups::AlgebraMatrixOf<G>>* out) {
  check_samples(where, "u_", u, method, false);
  const auto generators =
      map_samples(u, [&](const groups::TangentOf<G>& x) { return groups::AlgebraMatrixOf<G>(connection.transport_generator(x)); });
  return propagate_samples<MatrixAlgebra<groups::AlgebraMatrixOf<G>>>(where, generators, method,
                                                                     groups::AlgebraMatrixOf<G>::Identity(), out, true);
}

}  // namespace detail

/// P(s -> t_k) = Texp(-int_s^{t_k} nabla_{u(r)} dr) (cor-parr) at the nodes t_k = s + k (t - s)/steps,
/// for a curve whose velocity trivialised on the connection's side is u(r) (a function returning
/// G::Tangent): left connections take the body velocity g^{-1} g', right ones g' g^{-1}.
/// Validation as for ordered_exp_nodes.
template <groups::LieGroup G, class U>
std::vector<groups::AlgebraMatrixOf<G>> transport_operator_nodes(const connections::InvariantConnection<G>& connection,
                                                                 const U& u, double s, double t, int steps,
                                                                 TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::connection_function("transport_operator_nodes", connection, u, s, t, steps, method, &out);
  return out;
}

/// P(s -> t): the last node of transport_operator_nodes.
template <groups::LieGroup G, class U>
groups::AlgebraMatrixOf<G> transport_operator(const connections::InvariantConnection<G>& connection, const U& u, double s,
                                              double t, int steps, TransportMethod method) {
  return detail::connection_function("transport_operator", connection, u, s, t, steps, method, nullptr);
}

/// P(s -> t_k) from velocity samples u(t_k) (and u(t_k + h/2) for Magnus4) on [s, t] = [u.t0, u.t1].
template <groups::LieGroup G>
std::vector<groups::AlgebraMatrixOf<G>> transport_operator_nodes(const connections::InvariantConnection<G>& connection,
                                                                 const Samples<groups::TangentOf<G>>& u,
                                                                 TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::connection_samples("transport_operator_nodes", connection, u, method, &out);
  return out;
}

/// P(s -> t) from velocity samples: the last node of transport_operator_nodes.
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> transport_operator(const connections::InvariantConnection<G>& connection,
                                              const Samples<groups::TangentOf<G>>& u, TransportMethod method) {
  return detail::connection_samples("transport_operator", connection, u, method, nullptr);
}

// ------------------------------------------------------------------------------------------
// Cartan–Schouten fast path (parr-tran-Cartan-lambda, disc-exp)

namespace detail {

/// The coefficient c of the CS generator -c ad_u: lambda (left, CS-conn), lambda - 1 (right,
/// CS-conn-right).
inline double cartan_schouten_coefficient(std::string_view where, double lambda, groups::Side side) {
  require_finite(lambda, where, "lambda");
  return side == groups::Side::Left ? lambda : lambda - 1;
}

/// P = Ad(Y) at the last node, and at every node in *out, from Y at the nodes.
template <groups::LieGroup G, class Propagate>
groups::AlgebraMatrixOf<G> adjoint_of(const Propagate& propagate, std::vector<groups::AlgebraMatrixOf<G>>* out) {
  std::vector<groups::ElementOf<G>> ys;
  const groups::ElementOf<G> y = propagate(out != nullptr ? &ys : nullptr);
  if (out != nullptr) {
    out->clear();
    out->reserve(ys.size());
    for (const auto& yk : ys) out->push_back(G::Ad(yk));
  }
  return G::Ad(y);
}

/// P = Ad(Y) where Y' = -c u Y in G is integrated with the algebra-valued Magnus steps
/// (GroupAlgebra) from u as a function (checked, named "u(t)").
template <groups::LieGroup G, class U>
groups::AlgebraMatrixOf<G> cartan_schouten_function(std::string_view where, double lambda, groups::Side side, const U& u,
                                                    double s, double t, int steps, TransportMethod method,
                                                    std::vector<groups::AlgebraMatrixOf<G>>* out) {
  const double c = cartan_schouten_coefficient(where, lambda, side);
  const auto checked = checked_function<groups::TangentOf<G>>(where, "u", std::cref(u), G::kDim, 1);
  auto generator = [&checked, c](double r) { return groups::TangentOf<G>(-c * checked(r)); };
  return adjoint_of<G>([&](std::vector<groups::ElementOf<G>>* ys) {
    return propagate_function<GroupAlgebra<G>>(where, generator, s, t, steps, method, G::identity(), ys);
  }, out);
}

/// As above from velocity samples (checked and named u_nodes, u_midpoints).
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> cartan_schouten_samples(std::string_view where, double lambda, groups::Side side,
                                                   const Samples<groups::TangentOf<G>>& u, TransportMethod method,
                                                   std::vector<groups::AlgebraMatrixOf<G>>* out) {
  const double c = cartan_schouten_coefficient(where, lambda, side);
  check_samples(where, "u_", u, method, false);
  const auto generators = map_samples(u, [c](const groups::TangentOf<G>& x) { return groups::TangentOf<G>(-c * x); });
  return adjoint_of<G>([&](std::vector<groups::ElementOf<G>>* ys) {
    return propagate_samples<GroupAlgebra<G>>(where, generators, method, G::identity(), ys, false);
  }, out);
}

}  // namespace detail

/// P(s -> t_k) of the Cartan–Schouten connection of parameter lambda (parr-tran-Cartan-lambda) at
/// the nodes, for the velocity u trivialised on `side` (left: body velocity; right: g' g^{-1}),
/// computed in the algebra: P = Ad(Y), Y' = -c u Y in G (c = lambda left, lambda - 1 right).
/// Agrees with transport_operator_nodes(cartan_schouten<G>(lambda, side), ...) to rounding, for
/// every method.
template <groups::LieGroup G, class U>
std::vector<groups::AlgebraMatrixOf<G>> cartan_schouten_transport_nodes(double lambda, groups::Side side, const U& u,
                                                                        double s, double t, int steps,
                                                                        TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::cartan_schouten_function<G>("cartan_schouten_transport_nodes", lambda, side, u, s, t, steps, method, &out);
  return out;
}

/// P(s -> t): the last node of cartan_schouten_transport_nodes.
template <groups::LieGroup G, class U>
groups::AlgebraMatrixOf<G> cartan_schouten_transport(double lambda, groups::Side side, const U& u, double s, double t,
                                                     int steps, TransportMethod method) {
  return detail::cartan_schouten_function<G>("cartan_schouten_transport", lambda, side, u, s, t, steps, method, nullptr);
}

/// P(s -> t_k) from velocity samples, as transport_operator_nodes.
template <groups::LieGroup G>
std::vector<groups::AlgebraMatrixOf<G>> cartan_schouten_transport_nodes(double lambda, groups::Side side,
                                                                        const Samples<groups::TangentOf<G>>& u,
                                                                        TransportMethod method) {
  std::vector<groups::AlgebraMatrixOf<G>> out;
  detail::cartan_schouten_samples<G>("cartan_schouten_transport_nodes", lambda, side, u, method, &out);
  return out;
}

/// P(s -> t) from velocity samples: the last node.
template <groups::LieGroup G>
groups::AlgebraMatrixOf<G> cartan_schouten_transport(double lambda, groups::Side side,
                                                     const Samples<groups::TangentOf<G>>& u, TransportMethod method) {
  return detail::cartan_schouten_samples<G>("cartan_schouten_transport", lambda, side, u, method, nullptr);
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
