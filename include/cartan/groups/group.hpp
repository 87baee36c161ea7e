#pragma once
// The Lie group concept that every cartan algorithm is written against, and the operations
// derived from it once for all groups.
//
// Conventions (stated once here and in docs/conventions.md):
//  * The Lie algebra g = T_eG is represented in coordinates of a fixed basis {E_i}:
//    a `Tangent` v in R^n stands for hat(v) = sum_i v_i E_i.
//  * The dual g* is represented in the dual basis {theta^i}: a `Covector` mu in R^n pairs
//    with v as <mu, v> = mu . v.
//  * Linear maps on g (Ad_g, ad_u, transport operators P) are n x n matrices acting on
//    coordinate vectors; their duals on g* are the transposes (ad*_u = ad_u^T).
//  * Left trivialisation at the identity is the default: a tangent vector X at g is stored as
//    g^{-1}X in g (paper: d(L_{g^{-1}})_g X). Right-trivialised quantities say so in their names.
//  * An `Element` is a fixed-size Eigen object (a matrix for matrix groups, the coordinates
//    (a,b,c) for the Heisenberg group). A tangent vector at g in these ambient coordinates has
//    the same type as an Element: it is the derivative of an Element-valued curve. Covectors at
//    g in ambient coordinates pair with such tangent vectors entrywise (Frobenius pairing).

#include <Eigen/Dense>
#include <concepts>
#include <string_view>

namespace cartan::groups {

template <class G>
concept LieGroup = requires(const typename G::Element& g, const typename G::Tangent& v,
                            const typename G::MatrixRep& X) {
  requires std::same_as<typename G::Tangent, Eigen::Matrix<double, G::kDim, 1>>;
  requires std::same_as<typename G::AlgebraMatrix, Eigen::Matrix<double, G::kDim, G::kDim>>;
  { G::name() } -> std::convertible_to<std::string_view>;
  { G::identity() } -> std::same_as<typename G::Element>;
  { G::compose(g, g) } -> std::same_as<typename G::Element>;
  { G::inverse(g) } -> std::same_as<typename G::Element>;
  { G::exp(v) } -> std::same_as<typename G::Element>;
  { G::log(g) } -> std::same_as<typename G::Tangent>;
  { G::hat(v) } -> std::same_as<typename G::MatrixRep>;
  { G::vee(X) } -> std::same_as<typename G::Tangent>;
  { G::matrix(g) } -> std::same_as<typename G::MatrixRep>;  // faithful matrix representation
  { G::Ad(g) } -> std::same_as<typename G::AlgebraMatrix>;
  { G::ad(v) } -> std::same_as<typename G::AlgebraMatrix>;
  // d(L_g)_e v and d(R_g)_e v as tangent vectors at g in ambient coordinates.
  { G::left_translate(g, v) } -> std::same_as<typename G::Element>;
  { G::right_translate(g, v) } -> std::same_as<typename G::Element>;
  // Inverse maps: g^{-1} X and X g^{-1} for a tangent vector X at g (ambient coordinates).
  { G::left_trivialise(g, g) } -> std::same_as<typename G::Tangent>;
  { G::right_trivialise(g, g) } -> std::same_as<typename G::Tangent>;
  // Throws std::invalid_argument (naming the value) unless g is a valid element.
  { G::validate(g, std::string_view{}) } -> std::same_as<void>;
};

template <LieGroup G> using TangentOf = typename G::Tangent;
template <LieGroup G> using CovectorOf = typename G::Tangent;  // dual-basis coordinates
template <LieGroup G> using AlgebraMatrixOf = typename G::AlgebraMatrix;
template <LieGroup G> using ElementOf = typename G::Element;

/// Lie bracket [u, v] = ad_u v.
template <LieGroup G>
TangentOf<G> bracket(const TangentOf<G>& u, const TangentOf<G>& v) {
  return G::ad(u) * v;
}

/// log(a^{-1} b): the algebra element that left-translates a to b, b = a exp(log_between(a, b))
/// (within the injectivity radius of exp). For consecutive nodes of a curve it is h u_k.
template <LieGroup G>
TangentOf<G> log_between(const ElementOf<G>& a, const ElementOf<G>& b) {
  return G::log(G::compose(G::inverse(a), b));
}

/// Matrix of the coadjoint operator ad*_u on g*: <ad*_u mu, w> = <mu, ad_u w>, so ad*_u = ad_u^T.
template <LieGroup G>
AlgebraMatrixOf<G> coad(const TangentOf<G>& u) {
  return G::ad(u).transpose();
}

/// ad*_u mu.
template <LieGroup G>
CovectorOf<G> coad(const TangentOf<G>& u, const CovectorOf<G>& mu) {
  return G::ad(u).transpose() * mu;
}

/// Entrywise (Frobenius) pairing of an ambient covector with an ambient tangent vector.
template <LieGroup G>
double ambient_pairing(const ElementOf<G>& alpha, const ElementOf<G>& x) {
  return alpha.cwiseProduct(x).sum();
}

/// d(L_g)_e^* alpha: the left-trivialisation of an ambient covector alpha at g,
/// <d(L_g)^* alpha, v> = <alpha, d(L_g)_e v>.
template <LieGroup G>
CovectorOf<G> left_trivialise_covector(const ElementOf<G>& g, const ElementOf<G>& alpha) {
  CovectorOf<G> out;
  for (int i = 0; i < G::kDim; ++i) {
    out[i] = ambient_pairing<G>(alpha, G::left_translate(g, TangentOf<G>::Unit(i)));
  }
  return out;
}

/// d(R_g)_e^* alpha, the right-trivialisation of an ambient covector at g.
template <LieGroup G>
CovectorOf<G> right_trivialise_covector(const ElementOf<G>& g, const ElementOf<G>& alpha) {
  CovectorOf<G> out;
  for (int i = 0; i < G::kDim; ++i) {
    out[i] = ambient_pairing<G>(alpha, G::right_translate(g, TangentOf<G>::Unit(i)));
  }
  return out;
}

/// Left-trivialised derivative of a scalar function f at g along basis directions:
/// zeta_i = d/de f(g exp(e E_i)) at e = 0, by central differences with step `step`.
/// (A reference for tests and for user functions without an analytic gradient.)
template <LieGroup G, class F>
CovectorOf<G> left_gradient_fd(const F& f, const ElementOf<G>& g, double step = 1e-6) {
  CovectorOf<G> out;
  for (int i = 0; i < G::kDim; ++i) {
    const TangentOf<G> e = TangentOf<G>::Unit(i) * step;
    out[i] = (f(G::compose(g, G::exp(e))) - f(G::compose(g, G::exp(-e)))) / (2 * step);
  }
  return out;
}

}  // namespace cartan::groups
