#pragma once
// Connections with constant coefficients in a representation whose constant fields have a
// constant bracket: R^m with constant Christoffel symbols, and left-invariant connections on a
// Lie group in the left trivialisation. Both store the coefficients as matrices
// Gamma_i = (y -> Gamma(e_i, y)), and on both the covariant derivatives of T and R are algebraic:
//   (nabla_w T)(x, y)   = Gamma(w, T(x, y)) - T(Gamma(w, x), y) - T(x, Gamma(w, y))
//   (nabla_w R)(x, y) z = Gamma(w, R(x, y) z) - R(Gamma(w, x), y) z - R(x, Gamma(w, y)) z - R(x, y) Gamma(w, z)
// since T(x, y) and R(x, y) z of constant fields are constant fields.

#include <algorithm>
#include <array>

#include "cartan/manifolds/geometry.hpp"

namespace cartan::manifolds {

/// max over basis vectors of |nabla T| and |nabla R| (header comment), relative to the largest of
/// |Gamma|^2, |T| |Gamma|, |R| |Gamma| (so that the test below is scale-free).
template <ManifoldWithConnection M>
bool constant_coefficients_have_parallel_torsion_and_curvature(const M& manifold, const PointOf<M>& q) {
  constexpr int d = M::kAmbientDim;
  using V = VectorOf<M>;
  auto e = [](int i) { return V(V::Unit(i)); };
  auto gamma = [&](const V& x, const V& y) { return manifold.christoffel(q, x, y); };
  auto tor = [&](const V& x, const V& y) { return torsion(manifold, q, x, y); };
  auto cur = [&](const V& x, const V& y, const V& z) { return curvature(manifold, q, x, y, z); };
  double scale = 0, defect = 0;
  for (int w = 0; w < d; ++w) {
    for (int x = 0; x < d; ++x) {
      for (int y = 0; y < d; ++y) {
        const V t = tor(e(x), e(y));
        scale = std::max({scale, gamma(e(w), e(x)).norm(), t.norm()});
        defect = std::max(defect, (gamma(e(w), t) - tor(gamma(e(w), e(x)), e(y)) - tor(e(x), gamma(e(w), e(y)))).norm());
        for (int z = 0; z < d; ++z) {
          const V r = cur(e(x), e(y), e(z));
          scale = std::max(scale, r.norm());
          const V dr = gamma(e(w), r) - cur(gamma(e(w), e(x)), e(y), e(z)) - cur(e(x), gamma(e(w), e(y)), e(z)) -
                       cur(e(x), e(y), gamma(e(w), e(z)));
          defect = std::max(defect, dr.norm());
        }
      }
    }
  }
  return defect <= 1e-13 * std::max(1.0, scale * scale);
}

}  // namespace cartan::manifolds
