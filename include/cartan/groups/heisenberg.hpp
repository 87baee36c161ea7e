#pragma once
// The Heisenberg group H3 in the paper's coordinates (appendix "Nilpotent case: the
// three-dimensional Heisenberg group"): g(a,b,c) = [[1,a,c],[0,1,b],[0,0,1]],
//   g(a,b,c) g(a',b',c') = g(a+a', b+b', c+c'+ab'),   g(a,b,c)^{-1} = g(-a, -b, ab-c).
// Algebra basis E1 = d/da, E2 = d/db, E3 = d/dc at e with [E1,E2] = E3 (E3 central), so
// ad_u v = (0, 0, u1 v2 - u2 v1)  (ad-Heis). The dual basis is {da, db, dc} at e.
// An Element is the coordinate vector (a, b, c); tangent vectors at g are (a', b', c').

#include <Eigen/Dense>
#include <string_view>

namespace cartan::groups {

struct Heisenberg {
  static constexpr int kDim = 3;
  using Element = Eigen::Vector3d;  // (a, b, c)
  using Tangent = Eigen::Vector3d;  // (v1, v2, v3) in the basis E1, E2, E3
  using MatrixRep = Eigen::Matrix3d;
  using AlgebraMatrix = Eigen::Matrix3d;

  static constexpr std::string_view name() { return "heisenberg"; }
  static Element identity() { return Element::Zero(); }
  static Element compose(const Element& g, const Element& h) {
    return Element(g[0] + h[0], g[1] + h[1], g[2] + h[2] + g[0] * h[1]);
  }
  static Element inverse(const Element& g) { return Element(-g[0], -g[1], g[0] * g[1] - g[2]); }

  /// exp(v) = (v1, v2, v3 + v1 v2 / 2), exact (hat(v)^3 = 0); log is its inverse.
  static Element exp(const Tangent& v) { return Element(v[0], v[1], v[2] + v[0] * v[1] / 2); }
  static Tangent log(const Element& g);

  static MatrixRep hat(const Tangent& v);
  static Tangent vee(const MatrixRep& x);
  static MatrixRep matrix(const Element& g);

  /// Ad_g v = (v1, v2, v3 + a v2 - b v1).
  static AlgebraMatrix Ad(const Element& g) {
    AlgebraMatrix m = AlgebraMatrix::Identity();
    m(2, 0) = -g[1];
    m(2, 1) = g[0];
    return m;
  }
  /// (ad-Heis)
  static AlgebraMatrix ad(const Tangent& u) {
    AlgebraMatrix m = AlgebraMatrix::Zero();
    m(2, 0) = -u[1];
    m(2, 1) = u[0];
    return m;
  }
  /// Left Jacobian of exp, sum_k ad_v^k / (k+1)! = I + ad_v / 2 exactly (ad_v^2 = 0: ad_v maps into
  /// the centre, which it annihilates), and its inverse I - ad_v / 2.
  static AlgebraMatrix left_jacobian(const Tangent& v) { return AlgebraMatrix::Identity() + ad(v) / 2; }
  static AlgebraMatrix left_jacobian_inverse(const Tangent& v) { return AlgebraMatrix::Identity() - ad(v) / 2; }

  /// d(L_g)_e v = (v1, v2, v3 + a v2)  (left-Heis).
  static Element left_translate(const Element& g, const Tangent& v);
  /// d(R_g)_e v = (v1, v2, v3 + b v1).
  static Element right_translate(const Element& g, const Tangent& v);
  /// g^{-1} g' = (a', b', c' - a b')  (reduced-v-Heis).
  static Tangent left_trivialise(const Element& g, const Element& x);
  static Tangent right_trivialise(const Element& g, const Element& x);

  /// Every finite (a, b, c) is an element; throws std::invalid_argument otherwise.
  static void validate(const Element& g, std::string_view name);
};

}  // namespace cartan::groups
