#pragma once
// User-definable matrix Lie groups: a connected group G of n x n real matrices given by a basis
// {E_1, ..., E_d} of its Lie algebra g (a subspace of gl(n) closed under [X, Y] = XY - YX).
// Everything else is derived from the basis:
//   hat(v) = sum_i v_i E_i;
//   vee(X) = coordinates of the Frobenius-orthogonal projection of X onto span{E_i}:
//            vee(X) = Gram^{-1} (<E_i, X>)_i with Gram_ij = <E_i, E_j> = tr(E_i^T E_j);
//   [E_i, E_j] = sum_k c_ij^k E_k (structure constants), ad(u)_kj = sum_i u_i c_ij^k;
//   exp, log = the matrix exponential and principal matrix logarithm (Eigen);
//   Ad(g) e_j = vee(g E_j g^{-1}).
// Elements are the n x n matrices themselves (Element = MatrixRep).
//
// The generic group is the reference for closed-form groups (see SO3Generic and SE3Generic in
// se3.hpp, SE2Generic in se2.hpp) and a quick way to add a new group. Limits of the generic
// path: log needs g in the image of the principal logarithm (no eigenvalue of g on the closed
// negative real axis, e.g. a rotation by exactly pi is outside it), and exp/log cost a Schur
// decomposition each.

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <concepts>
#include <string>
#include <string_view>
#include <unsupported/Eigen/MatrixFunctions>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/numerics/spectrum.hpp"

namespace cartan::groups {

/// What a user supplies to define a matrix Lie group: dimensions, a name and the basis E_i.
template <class B>
concept MatrixLieAlgebraBasis = requires {
  requires B::kDim >= 1;
  requires B::kMatrixSize >= 1;
  requires B::kDim <= B::kMatrixSize * B::kMatrixSize;
  { B::name() } -> std::convertible_to<std::string_view>;
  { B::basis() } -> std::same_as<std::array<Eigen::Matrix<double, B::kMatrixSize, B::kMatrixSize>, B::kDim>>;
};

template <MatrixLieAlgebraBasis Basis>
struct MatrixLieGroup {
  static constexpr int kDim = Basis::kDim;
  static constexpr int kMatrixSize = Basis::kMatrixSize;
  using Element = Eigen::Matrix<double, kMatrixSize, kMatrixSize>;
  using Tangent = Eigen::Matrix<double, kDim, 1>;
  using MatrixRep = Element;
  using AlgebraMatrix = Eigen::Matrix<double, kDim, kDim>;
  using BasisMatrices = std::array<MatrixRep, kDim>;

  /// The basis is rejected unless its Gram matrix has condition number below this (so that vee
  /// loses at most ~6 of 16 digits)...
  static constexpr double kMaxGramCondition = 1e12;
  /// ...and unless every [E_i, E_j] is within this distance (max entry, relative to
  /// max(1, max|[E_i, E_j]|)) of its projection onto span{E_k}.
  static constexpr double kClosureTolerance = 1e-12;
  /// Default tolerance of `validate`: max|exp(log g) - g| <= tolerance * max(1, max|g|).
  static constexpr double kDefaultTolerance = 1e-9;

  static constexpr std::string_view name() { return Basis::name(); }

  /// The basis E_i, checked (linearly independent, closed under the bracket) on first use.
  static const BasisMatrices& basis() { return algebra().basis; }
  /// Throws std::invalid_argument, naming the offending matrix, unless the basis is valid.
  static void check_basis() { (void)algebra(); }
  /// structure_constants()[i](k, j) = c_ij^k, where [E_i, E_j] = sum_k c_ij^k E_k; the i-th
  /// matrix is ad(E_i).
  static const std::array<AlgebraMatrix, kDim>& structure_constants() { return algebra().structure_constants; }
  /// The Frobenius Gram matrix Gram_ij = <E_i, E_j>.
  static const AlgebraMatrix& gram() { return algebra().gram; }

  static Element identity() { return Element::Identity(); }
  static Element compose(const Element& a, const Element& b) { return a * b; }
  static Element inverse(const Element& g) { return g.inverse(); }

  static Element exp(const Tangent& v) { return hat(v).exp(); }
  /// vee of the principal matrix logarithm (see the limits above).
  static Tangent log(const Element& g) { return vee(g.log()); }

  static MatrixRep hat(const Tangent& v) {
    const BasisMatrices& e = basis();
    MatrixRep x = MatrixRep::Zero();
    for (int i = 0; i < kDim; ++i) x += v[i] * e[i];
    return x;
  }
  /// Coordinates of the Frobenius projection of x onto the algebra: vee(x)_i = <D_i, x> with
  /// the dual basis D_i = sum_j (Gram^{-1})_ij E_j, so vee(hat(v)) = v.
  static Tangent vee(const MatrixRep& x) {
    const BasisMatrices& dual = algebra().dual_basis;
    Tangent v;
    for (int i = 0; i < kDim; ++i) v[i] = dual[i].cwiseProduct(x).sum();
    return v;
  }
  static MatrixRep matrix(const Element& g) { return g; }

  /// Ad(g) e_j = vee(g E_j g^{-1}).
  static AlgebraMatrix Ad(const Element& g) {
    const BasisMatrices& e = basis();
    const Element g_inv = inverse(g);
    AlgebraMatrix m;
    for (int j = 0; j < kDim; ++j) m.col(j) = vee(g * e[j] * g_inv);
    return m;
  }
  /// ad(u) = sum_i u_i ad(E_i), from the structure constants.
  static AlgebraMatrix ad(const Tangent& u) {
    const std::array<AlgebraMatrix, kDim>& c = structure_constants();
    AlgebraMatrix m = AlgebraMatrix::Zero();
    for (int i = 0; i < kDim; ++i) m += u[i] * c[i];
    return m;
  }

  static Element left_translate(const Element& g, const Tangent& v) { return g * hat(v); }
  static Element right_translate(const Element& g, const Tangent& v) { return hat(v) * g; }
  static Tangent left_trivialise(const Element& g, const Element& x) { return vee(inverse(g) * x); }
  static Tangent right_trivialise(const Element& g, const Element& x) { return vee(x * inverse(g)); }

  /// Throws std::invalid_argument naming `name` and the matrix unless the basis is valid, g is
  /// finite and exp(log g) = g within kDefaultTolerance (so g = exp of an algebra element).
  static void validate(const Element& g, std::string_view name) { validate(g, name, kDefaultTolerance); }
  static void validate(const Element& g, std::string_view name, double tolerance) {
    check_basis();
    const std::string where = "MatrixLieGroup<" + std::string(Basis::name()) + ">";
    require_finite(g, where, name);
    const double scale = std::max(1.0, g.cwiseAbs().maxCoeff());
    const double residual = (exp(log(g)) - g).cwiseAbs().maxCoeff();
    if (!(residual <= tolerance * scale)) {  // also rejects a NaN residual
      throw_invalid(where, name, format_value(g),
                    "is not in the group: max|exp(log g) - g| = " + format_value(residual) + " > tolerance " +
                        format_value(tolerance * scale) +
                        " (g is off the group, or has an eigenvalue on the closed negative real axis "
                        "where the principal logarithm is undefined)");
    }
  }

 private:
  struct Algebra {
    BasisMatrices basis;
    AlgebraMatrix gram;
    BasisMatrices dual_basis;
    std::array<AlgebraMatrix, kDim> structure_constants;
  };

  /// Computed and checked once (a function-local static); if the check throws, the next call
  /// tries again and throws again.
  static const Algebra& algebra() {
    static const Algebra cached = make_algebra();
    return cached;
  }

  static std::string basis_element_name(int i) {
    std::string out = "E";
    out += std::to_string(i + 1);
    return out;
  }

  static Algebra make_algebra() {
    const std::string where = "MatrixLieGroup<" + std::string(Basis::name()) + ">";
    Algebra a;
    a.basis = Basis::basis();
    for (int i = 0; i < kDim; ++i) require_finite(a.basis[i], where, basis_element_name(i));

    for (int i = 0; i < kDim; ++i) {
      for (int j = 0; j < kDim; ++j) a.gram(i, j) = a.basis[i].cwiseProduct(a.basis[j]).sum();
    }
    const Eigen::VectorXd spectrum = numerics::symmetric_eigenvalues(a.gram);
    const double largest = spectrum.maxCoeff();
    const double smallest = spectrum.minCoeff();
    if (!(smallest * kMaxGramCondition > largest)) {
      throw_invalid(where, "Gram matrix of the basis", format_value(a.gram),
                    "is singular or ill-conditioned (eigenvalues " + format_value(smallest) + " .. " +
                        format_value(largest) + "): the basis is not linearly independent");
    }
    // LDLT (no square roots) keeps Gram^{-1} exact for the usual bases of 0/+-1 matrices.
    const AlgebraMatrix gram_inverse = a.gram.ldlt().solve(AlgebraMatrix::Identity());
    for (int i = 0; i < kDim; ++i) {
      a.dual_basis[i] = MatrixRep::Zero();
      for (int j = 0; j < kDim; ++j) a.dual_basis[i] += gram_inverse(i, j) * a.basis[j];
    }

    for (int i = 0; i < kDim; ++i) {
      for (int j = 0; j < kDim; ++j) {
        const MatrixRep commutator = a.basis[i] * a.basis[j] - a.basis[j] * a.basis[i];
        MatrixRep projection = MatrixRep::Zero();
        for (int k = 0; k < kDim; ++k) {
          const double c = a.dual_basis[k].cwiseProduct(commutator).sum();
          a.structure_constants[i](k, j) = c;
          projection += c * a.basis[k];
        }
        const double residual = (commutator - projection).cwiseAbs().maxCoeff();
        const double scale = std::max(1.0, commutator.cwiseAbs().maxCoeff());
        if (!(residual <= kClosureTolerance * scale)) {
          std::string bracket_name = "[";  // built with += : GCC 12 warns wrongly on "..." + string
          bracket_name += basis_element_name(i);
          bracket_name += ", ";
          bracket_name += basis_element_name(j);
          bracket_name += "]";
          throw_invalid(where, bracket_name, format_value(commutator),
                        "is not in the span of the basis (distance " + format_value(residual) +
                            "): the basis is not closed under the bracket");
        }
      }
    }
    return a;
  }
};

}  // namespace cartan::groups
