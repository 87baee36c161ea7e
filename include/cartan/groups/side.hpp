#pragma once
// Left and right: the side on which a connection, a velocity or a covector is trivialised, and
// the translations between ambient coordinates at g (tangent vectors and covectors at points of
// G) and their trivialisations in the Lie algebra (paper §3; the right versions in appendix
// "Right formalism").

#include <array>
#include <string_view>

#include "cartan/groups/group.hpp"

namespace cartan::groups {

/// Which trivialisation a connection's bilinear map refers to.
enum class Side { Left, Right };

inline std::string_view to_string(Side s) { return s == Side::Left ? "left" : "right"; }

/// g^{-1} X (left) or X g^{-1} (right) for a tangent vector X at g in ambient coordinates.
template <LieGroup G>
TangentOf<G> trivialise(Side side, const ElementOf<G>& g, const ElementOf<G>& x) {
  return side == Side::Left ? G::left_trivialise(g, x) : G::right_trivialise(g, x);
}

/// g x (left) or x g (right): the tangent vector at g, in ambient coordinates.
template <LieGroup G>
ElementOf<G> translate(Side side, const ElementOf<G>& g, const TangentOf<G>& x) {
  return side == Side::Left ? G::left_translate(g, x) : G::right_translate(g, x);
}

/// d(L_g)^* alpha (left) or d(R_g)^* alpha (right) of an ambient covector alpha at g.
template <LieGroup G>
CovectorOf<G> trivialise_covector(Side side, const ElementOf<G>& g, const ElementOf<G>& alpha) {
  return side == Side::Left ? left_trivialise_covector<G>(g, alpha) : right_trivialise_covector<G>(g, alpha);
}

/// The ambient covector at g whose trivialisation is eta: the unique one tangent to G, i.e.
/// sum_j c_j B_j with B_j = translate(g, E_j) and Gram c = eta, Gram_ij = <B_i, B_j>
/// (entrywise pairing). Where the ambient space is T_gG itself (H3's (a, b, c)) it is the only
/// one: for the left side on H3 this is d(L_{g^{-1}})^* eta = (eta_1, eta_2 - a eta_3, eta_3).
template <LieGroup G>
ElementOf<G> untrivialise_covector(Side side, const ElementOf<G>& g, const CovectorOf<G>& eta) {
  std::array<ElementOf<G>, G::kDim> basis;
  for (int i = 0; i < G::kDim; ++i) basis[i] = translate<G>(side, g, TangentOf<G>::Unit(i));
  AlgebraMatrixOf<G> gram;
  for (int i = 0; i < G::kDim; ++i) {
    for (int j = 0; j < G::kDim; ++j) gram(i, j) = ambient_pairing<G>(basis[i], basis[j]);
  }
  const TangentOf<G> c = gram.ldlt().solve(eta);
  ElementOf<G> out = ElementOf<G>::Zero();
  for (int j = 0; j < G::kDim; ++j) out += c[j] * basis[j];
  return out;
}

}  // namespace cartan::groups
