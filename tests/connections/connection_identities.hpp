#pragma once
// Reusable checks of invariant connections (STYLE.md practice 5): the general torsion and
// curvature formulas against the Cartan–Schouten closed forms and against the first Bianchi
// identity, and bi-invariance of Cartan–Schouten connections on vector fields.

#include "cartan/cartan_schouten.hpp"
#include "test_support.hpp"

namespace cartan::testing {

/// A random bilinear map (seeded), as a connection on the given side.
template <LieGroup G>
InvariantConnection<G> random_connection(Side side, std::mt19937& rng) {
  typename InvariantConnection<G>::Coefficients c;
  for (auto& m : c) m = random_vector<Eigen::Matrix<double, G::kDim * G::kDim, 1>>(rng, 1.0).reshaped(G::kDim, G::kDim);
  return InvariantConnection<G>(side, c);
}

/// First Bianchi identity with torsion, on invariant fields (valid for every connection):
///   cyc R(u,v)w = cyc [ T(T(u,v), w) + (nabla_u T)(v, w) ],
///   (nabla_u T)(v,w) = nabla_u T(v,w) - T(nabla_u v, w) - T(v, nabla_u w).
/// Returns the defect (should vanish to rounding).
template <LieGroup G>
TangentOf<G> bianchi_defect(const InvariantConnection<G>& c, const TangentOf<G>& u, const TangentOf<G>& v,
                            const TangentOf<G>& w) {
  auto dT = [&](const TangentOf<G>& x, const TangentOf<G>& y, const TangentOf<G>& z) {
    return TangentOf<G>(c.nabla(x, c.torsion(y, z)) - c.torsion(c.nabla(x, y), z) - c.torsion(y, c.nabla(x, z)));
  };
  auto term = [&](const TangentOf<G>& x, const TangentOf<G>& y, const TangentOf<G>& z) {
    return TangentOf<G>(c.curvature(x, y, z) - c.torsion(c.torsion(x, y), z) - dT(x, y, z));
  };
  return term(u, v, w) + term(v, w, u) + term(w, u, v);
}

/// A smooth (non-invariant) vector field on G in ambient coordinates: X(g) = d(L_g)_e f(g),
/// with f(g) = sin(M vec(matrix(g))) for a fixed seeded matrix M.
template <LieGroup G>
struct SmoothField {
  using Mat = typename G::MatrixRep;
  Eigen::Matrix<double, G::kDim, Mat::SizeAtCompileTime> m;
  explicit SmoothField(std::mt19937& rng) {
    m = random_vector<Eigen::Matrix<double, G::kDim * Mat::SizeAtCompileTime, 1>>(rng, 1.0)
            .reshaped(G::kDim, Mat::SizeAtCompileTime);
  }
  ElementOf<G> operator()(const ElementOf<G>& g) const {
    const Mat x = G::matrix(g);
    const TangentOf<G> f = (m * x.reshaped()).array().sin().matrix();
    return G::left_translate(g, f);
  }
};

/// nabla_V W at g computed from a connection's left or right description: trivialise the
/// fields on the connection's side, differentiate the trivialised W along the curve
/// g exp(e g^{-1} V_g) by central differences (step 1e-5: error ~1e-10), apply
/// (eq:left-conn) and translate back to ambient coordinates.
template <LieGroup G, class F>
ElementOf<G> covariant_derivative_of_fields(const InvariantConnection<G>& c, const F& field_v, const F& field_w,
                                            const ElementOf<G>& g) {
  const bool left = c.side() == Side::Left;
  auto trivialise = [&](const ElementOf<G>& x, const ElementOf<G>& tangent) {
    return left ? G::left_trivialise(x, tangent) : G::right_trivialise(x, tangent);
  };
  const ElementOf<G> vg = field_v(g);
  const TangentOf<G> body = G::left_trivialise(g, vg);
  const double h = 1e-5;
  const ElementOf<G> gp = G::compose(g, G::exp(h * body));
  const ElementOf<G> gm = G::compose(g, G::exp(-h * body));
  const TangentOf<G> dw = (trivialise(gp, field_w(gp)) - trivialise(gm, field_w(gm))) / (2 * h);
  const TangentOf<G> result = c.covariant_derivative(trivialise(g, vg), trivialise(g, field_w(g)), dw);
  return left ? G::left_translate(g, result) : G::right_translate(g, result);
}

}  // namespace cartan::testing
