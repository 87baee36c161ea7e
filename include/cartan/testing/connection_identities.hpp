#pragma once
// Reusable checks of invariant connections (STYLE.md practice 5), installed for users who build
// their own connection (an InvariantConnection<G> from a table, or a class of their own, on a
// built-in group or their own):
//
//   #include <cartan/testing/connection_identities.hpp>
//   TEST(MyConnection, Identities) { cartan::testing::expect_connection_identities<G>(my_connection); }
//
//   expect_connection_identities<G>(c)  at 10 seeded random triples (u, v, w), coordinates in
//                                    [-1, 1]: torsion and curvature against their definitions from
//                                    nabla and the group's bracket (cur-tor-left), T(v, w) = -T(w, v),
//                                    R(u, v) w = -R(v, u) w, and the first Bianchi identity with
//                                    torsion (bianchi_defect; it fails for a bracket that breaks
//                                    Jacobi); tolerance 1e-12 (1 + |Gamma|^3): each side is a sum of
//                                    products of up to three coefficient matrices, exact up to rounding.
//                                    c: an InvariantConnection<G>, or your own class with nabla,
//                                    torsion, curvature and side()
//   bianchi_defect(c, u, v, w)       the defect of that identity (zero up to rounding)
//   random_connection<G>(side, rng)  a seeded random bilinear map
//   SmoothField, covariant_derivative_of_fields  nabla_V W of non-invariant fields by differences
// Needs GoogleTest (link GTest::gtest); the library never includes cartan/testing/.

#include <algorithm>

#include "cartan/connections/cartan_schouten.hpp"
#include "cartan/testing/support.hpp"

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
/// Returns the defect (should vanish to rounding). C: InvariantConnection<G> or any class with
/// nabla(u, w), torsion(v, w) and curvature(u, v, w) on algebra vectors.
template <groups::LieGroup G, class C>
groups::TangentOf<G> bianchi_defect(const C& c, const groups::TangentOf<G>& u, const groups::TangentOf<G>& v,
                                    const groups::TangentOf<G>& w) {
  using T = groups::TangentOf<G>;
  auto dT = [&](const T& x, const T& y, const T& z) {
    return T(c.nabla(x, c.torsion(y, z)) - c.torsion(c.nabla(x, y), z) - c.torsion(y, c.nabla(x, z)));
  };
  auto term = [&](const T& x, const T& y, const T& z) {
    return T(c.curvature(x, y, z) - c.torsion(c.torsion(x, y), z) - dT(x, y, z));
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

/// The connection's torsion and curvature against their definitions from nabla (cur-tor-left;
/// the right side flips the bracket terms), their antisymmetry and the first Bianchi identity
/// with torsion (the header's comment), at 10 seeded random triples. C as for bianchi_defect, with
/// side() (groups::Side).
template <groups::LieGroup G, class C>
void expect_connection_identities(const C& c) {
  using T = groups::TangentOf<G>;
  double size = 0;  // the largest |nabla_{E_i} E_j|: the identities' terms scale up to size^3
  for (int i = 0; i < G::kDim; ++i) {
    for (int j = 0; j < G::kDim; ++j) size = std::max(size, T(c.nabla(T::Unit(i), T::Unit(j))).cwiseAbs().maxCoeff());
  }
  const double tolerance = 1e-12 * (1 + size * size * size);
  const double sign = c.side() == groups::Side::Left ? 1 : -1;
  std::mt19937 rng(kSeed + 11);
  for (int trial = 0; trial < 10; ++trial) {
    const T u = random_tangent<G>(rng), v = random_tangent<G>(rng), w = random_tangent<G>(rng);
    const T torsion = c.nabla(v, w) - c.nabla(w, v) - sign * groups::bracket<G>(v, w);
    EXPECT_NEAR_MATRIX(c.torsion(v, w), torsion, tolerance) << "torsion formula, trial " << trial;
    const T curvature = c.nabla(u, T(c.nabla(v, w))) - c.nabla(v, T(c.nabla(u, w))) - sign * c.nabla(groups::bracket<G>(u, v), w);
    EXPECT_NEAR_MATRIX(c.curvature(u, v, w), curvature, tolerance) << "curvature formula, trial " << trial;
    EXPECT_NEAR_MATRIX(c.torsion(v, w), -c.torsion(w, v), tolerance) << "torsion antisymmetry, trial " << trial;
    EXPECT_NEAR_MATRIX(c.curvature(u, v, w), -c.curvature(v, u, w), tolerance)
        << "curvature antisymmetry, trial " << trial;
    EXPECT_LE(bianchi_defect<G>(c, u, v, w).cwiseAbs().maxCoeff(), tolerance) << "first Bianchi identity, trial " << trial;
  }
}

}  // namespace cartan::testing
