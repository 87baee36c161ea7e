#pragma once
// Natural mechanical systems on a Lie group, left-reduced: kinetic energy from a constant
// inertia (a symmetric positive-definite map g -> g*) minus a potential,
//   l(g, v) = 1/2 v . I v - V(g),          h(g, mu) = 1/2 mu . I^{-1} mu + V(g),
// Legendre-related by mu = I v (paper §4, "The reduced Legendre transform").
// Group gradients (left-trivialised, lagrangian.hpp): zeta_l = -dV, zeta_h = +dV, where
// dV . w = d/de V(g exp(e w)). The right-reduced forms are in mechanics/right_reduced.hpp.
//
// A Potential type provides `double value(g)` and `Covector left_gradient(g)` (= dV above), and
// optionally `left_hessian(g)`: the matrix whose column i is d/de dV(g exp(e E_i)) (central
// differences of dV are used when it is missing).

#include <Eigen/Cholesky>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "cartan/errors.hpp"
#include "cartan/groups/group.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"
#include "cartan/numerics/spectrum.hpp"

namespace cartan::mechanics {

template <class P, class G>
concept Potential = groups::LieGroup<G> && requires(const P& p, const groups::ElementOf<G>& g) {
  { p.value(g) } -> std::convertible_to<double>;
  { p.left_gradient(g) } -> std::convertible_to<groups::CovectorOf<G>>;
};

/// V = 0 (free motion).
template <groups::LieGroup G>
struct ZeroPotential {
  double value(const groups::ElementOf<G>&) const { return 0; }
  groups::CovectorOf<G> left_gradient(const groups::ElementOf<G>&) const { return groups::CovectorOf<G>::Zero(); }
  groups::AlgebraMatrixOf<G> left_hessian(const groups::ElementOf<G>&) const { return groups::AlgebraMatrixOf<G>::Zero(); }
};

/// Column i: d/de dV(g exp(e E_i)), from the potential or by central differences (step 1e-5).
template <groups::LieGroup G, Potential<G> V>
groups::AlgebraMatrixOf<G> potential_left_hessian(const V& potential, const groups::ElementOf<G>& g) {
  if constexpr (requires { { potential.left_hessian(g) } -> std::convertible_to<groups::AlgebraMatrixOf<G>>; }) {
    return potential.left_hessian(g);
  } else {
    groups::AlgebraMatrixOf<G> out;
    for (int i = 0; i < G::kDim; ++i) {
      const groups::TangentOf<G> e = groups::TangentOf<G>::Unit(i) * kHessianStep;
      out.col(i) = (groups::CovectorOf<G>(potential.left_gradient(G::compose(g, G::exp(e)))) -
                    groups::CovectorOf<G>(potential.left_gradient(G::compose(g, G::exp(groups::TangentOf<G>(-e)))))) /
                   (2 * kHessianStep);
    }
    return out;
  }
}

/// A validated inertia: symmetric (to relative 1e-12; then symmetrised exactly), finite and
/// positive definite (smallest eigenvalue > 1e-14 x largest). Throws std::invalid_argument
/// naming `where`, "inertia" and the matrix otherwise.
template <int N>
class Inertia {
 public:
  using Matrix = Eigen::Matrix<double, N, N>;
  using Vector = Eigen::Matrix<double, N, 1>;

  Inertia(const Matrix& inertia, std::string_view where) {
    require_finite(inertia, where, "inertia");
    const double scale = inertia.cwiseAbs().maxCoeff();
    const double asymmetry = (inertia - inertia.transpose()).cwiseAbs().maxCoeff();
    if (asymmetry > 1e-12 * scale) {
      throw_invalid(where, "inertia", format_value(inertia),
                    "is not symmetric: max|I - I^T| = " + format_value(asymmetry));
    }
    matrix_ = (inertia + inertia.transpose()) / 2;
    const Eigen::VectorXd eigenvalues = numerics::symmetric_eigenvalues(matrix_);
    if (!(eigenvalues.minCoeff() > 1e-14 * eigenvalues.maxCoeff()) || !(eigenvalues.maxCoeff() > 0)) {
      throw_invalid(where, "inertia", format_value(inertia),
                    "is not positive definite: eigenvalues " + format_value(eigenvalues));
    }
    inverse_ = Eigen::LLT<Matrix>(matrix_).solve(Matrix::Identity());
    inverse_ = (inverse_ + inverse_.transpose()).eval() / 2;
  }

  const Matrix& matrix() const { return matrix_; }
  Vector apply(const Vector& v) const { return matrix_ * v; }
  /// I^{-1} mu by the inverse computed once (Cholesky, symmetrised): a product instead of two
  /// triangular solves with divisions on every call (the inverse Legendre map sits in every
  /// right-hand side; bench/README.md, "inverse inertia"). Errors: cond(I) eps |mu|.
  Vector solve(const Vector& mu) const { return inverse_ * mu; }

 private:
  Matrix matrix_;
  Matrix inverse_;
};

/// What a natural Lagrangian and its Hamiltonian share: the inertia, the potential, and the
/// velocity v = I^{-1} mu (inverse Legendre map of l, and dh/dmu).
template <groups::LieGroup G, Potential<G> V>
class NaturalSystem {
 public:
  using InertiaMatrix = groups::AlgebraMatrixOf<G>;

  groups::TangentOf<G> velocity(double, const groups::ElementOf<G>&, const groups::CovectorOf<G>& mu) const { return inertia_.solve(mu); }
  const InertiaMatrix& inertia() const { return inertia_.matrix(); }
  const V& potential() const { return potential_; }

 protected:
  NaturalSystem(const InertiaMatrix& inertia, V potential, std::string_view model)
      : inertia_(inertia, std::string(model) + "<" + std::string(G::name()) + ">"), potential_(std::move(potential)) {}
  double kinetic_energy_of_velocity(const groups::TangentOf<G>& v) const { return v.dot(inertia_.apply(v)) / 2; }
  double kinetic_energy_of_momentum(const groups::CovectorOf<G>& mu) const { return mu.dot(inertia_.solve(mu)) / 2; }
  groups::CovectorOf<G> momentum_of(const groups::TangentOf<G>& v) const { return inertia_.apply(v); }

 private:
  Inertia<G::kDim> inertia_;
  V potential_;
};

/// l(t, g, v) = 1/2 v . I v - V(g), left-reduced.
template <groups::LieGroup G, Potential<G> V>
class NaturalLagrangian : public NaturalSystem<G, V> {
 public:
  explicit NaturalLagrangian(const groups::AlgebraMatrixOf<G>& inertia, V potential = {})
      : NaturalSystem<G, V>(inertia, std::move(potential), "NaturalLagrangian") {}
  // Hessian structure (lagrangian_hessian.hpp): mu = I v; zeta = -dV depends on g only.
  static constexpr bool kConstantMomentumHessian = true;
  static constexpr bool kGroupGradientIndependentOfVelocity = true;
  static constexpr bool kZeroGroupGradient = std::is_same_v<V, ZeroPotential<G>>;

  double value(double, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return this->kinetic_energy_of_velocity(v) - this->potential().value(g);
  }
  groups::CovectorOf<G> momentum(double, const groups::ElementOf<G>&, const groups::TangentOf<G>& v) const { return this->momentum_of(v); }
  groups::CovectorOf<G> group_gradient(double, const groups::ElementOf<G>& g, const groups::TangentOf<G>&) const {
    return -this->potential().left_gradient(g);
  }
  /// Analytic second derivatives (lagrangian_hessian.hpp): mu = I v depends on v only and
  /// zeta = -dV on g only, so d mu/dv = I, d zeta/d gamma = -(the potential's left Hessian).
  LagrangianHessian<G> hessian(double, const groups::ElementOf<G>& g, const groups::TangentOf<G>&) const {
    return {.momentum_v = this->inertia(),
            .momentum_g = groups::AlgebraMatrixOf<G>::Zero(),
            .gradient_v = groups::AlgebraMatrixOf<G>::Zero(),
            .gradient_g = -potential_left_hessian<G>(this->potential(), g)};
  }
};

/// h(t, g, mu) = 1/2 mu . I^{-1} mu + V(g), left-reduced; the Legendre transform of
/// NaturalLagrangian<G, V> with the same inertia.
template <groups::LieGroup G, Potential<G> V>
class NaturalHamiltonian : public NaturalSystem<G, V> {
 public:
  explicit NaturalHamiltonian(const groups::AlgebraMatrixOf<G>& inertia, V potential = {})
      : NaturalSystem<G, V>(inertia, std::move(potential), "NaturalHamiltonian") {}

  double value(double, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return this->kinetic_energy_of_momentum(mu) + this->potential().value(g);
  }
  groups::CovectorOf<G> group_gradient(double, const groups::ElementOf<G>& g, const groups::CovectorOf<G>&) const {
    return this->potential().left_gradient(g);
  }
};

}  // namespace cartan::mechanics
