#pragma once
// Reusable checks of invariant connections (STYLE.md practice 5): the general torsion and
// curvature formulas against the Cartan–Schouten closed forms and against the first Bianchi
// identity, and bi-invariance of Cartan–Schouten connections on vector fields.

#include "cartan/connections/cartan_schouten.hpp"
#include "test_support.hpp"

namespace cartan::testing {

/// A random bilinear map (seeded), as a connection on the given side.
template <groups::LieGroup G>
connections::InvariantConnection<G> random_connection(groups::Side side, std::mt19937& rng) {
  typename connections::InvariantConnection<G>::Coefficients c;
  for (auto& m : c) m = random_vector<Eigen::Matrix<double, G::kDim * G::kDim, 1>>(rng, 1.0).reshaped(G::kDim, G::kDim);
  return connections::InvariantConnection<G>(side, c);
}

/// First Bianchi identity with torsion, on invariant fields (valid for every connection):
///   cyc R(u,v)w = cyc [ T(T(u,v), w) + (nabla_u T)(v, w) ],
///   (nabla_u T)(v,w) = nabla_u T(v,w) - T(nabla_u v, w) - T(v, nabla_u w).
/// Returns the defect (should vanish to rounding).
template <groups::LieGroup G>
groups::TangentOf<G> bianchi_defect(const connections::InvariantConnection<G>& c, const groups::TangentOf<G>& u, const groups::TangentOf<G>& v,
                            const groups::TangentOf<G>& w) {
  auto dT = [&](const groups::TangentOf<G>& x, const groups::TangentOf<G>& y, const groups::TangentOf<G>& z) {
    return groups::TangentOf<G>(c.nabla(x, c.torsion(y, z)) - c.torsion(c.nabla(x, y), z) - c.torsion(y, c.nabla(x, z)));
  };
  auto term = [&](const groups::TangentOf<G>& x, const groups::TangentOf<G>& y, const groups::TangentOf<G>& z) {
    return groups::TangentOf<G>(c.curvature(x, y, z) - c.torsion(c.torsion(x, y), z) - dT(x, y, z));
  };
  return term(u, v, w) + term(v, w, u) + term(w, u, v);
}

/// A smooth (non-invariant) vector field on G in ambient coordinates: X(g) = d(L_g)_e f(g),
/// with f(g) = sin(M vec(matrix(g))) for a fixed seeded matrix M.
template <groups::LieGroup G>
struct SmoothField {
  using Mat = typename G::MatrixRep;
  Eigen::Matrix<double, G::kDim, Mat::SizeAtCompileTime> m;
  explicit SmoothField(std::mt19937& rng) {
    m = random_vector<Eigen::Matrix<double, G::kDim * Mat::SizeAtCompileTime, 1>>(rng, 1.0)
            .reshaped(G::kDim, Mat::SizeAtCompileTime);
  }
  groups::ElementOf<G> operator()(const groups::ElementOf<G>& g) const {
    const Mat x = G::matrix(g);
    const groups::TangentOf<G> f = (m * x.reshaped()).array().sin().matrix();
    return G::left_translate(g, f);
  }
};

/// nabla_V W at g computed from a connection's left or right description: trivialise the
/// fields on the connection's side, differentiate the trivialised W along the curve
/// g exp(e g^{-1} V_g) by central differences (step 1e-5: error ~1e-10), apply
/// (eq:left-conn) and translate back to ambient coordinates.
template <groups::LieGroup G, class F>
groups::ElementOf<G> covariant_derivative_of_fields(const connections::InvariantConnection<G>& c, const F& field_v, const F& field_w,
                                            const groups::ElementOf<G>& g) {
  const bool left = c.side() == groups::Side::Left;
  auto trivialise = [&](const groups::ElementOf<G>& x, const groups::ElementOf<G>& tangent) {
    return left ? G::left_trivialise(x, tangent) : G::right_trivialise(x, tangent);
  };
  const groups::ElementOf<G> vg = field_v(g);
  const groups::TangentOf<G> body = G::left_trivialise(g, vg);
  const double h = 1e-5;
  const groups::ElementOf<G> gp = G::compose(g, G::exp(h * body));
  const groups::ElementOf<G> gm = G::compose(g, G::exp(-h * body));
  const groups::TangentOf<G> dw = (trivialise(gp, field_w(gp)) - trivialise(gm, field_w(gm))) / (2 * h);
  const groups::TangentOf<G> result = c.covariant_derivative(trivialise(g, vg), trivialise(g, field_w(g)), dw);
  return left ? G::left_translate(g, result) : G::right_translate(g, result);
}

}  // namespace cartan::testing
