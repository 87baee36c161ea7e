#pragma once
// R^m with a constant linear connection nabla_{e_i} e_j = Gamma^k_ij e_k: any torsion
// T^k_ij = Gamma^k_ij - Gamma^k_ji and curvature R(x, y) z = Gamma(x, Gamma(y, z)) - Gamma(y, Gamma(x, z))
// (geometry.hpp with D Gamma = 0 and no bracket), a clean test bed for the general theory.
// Gamma = 0 is flat and torsion-free: the transported velocity is the velocity.

#include <array>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

#include "cartan/errors.hpp"
#include "cartan/manifolds/constant_connection.hpp"
#include "cartan/manifolds/derivatives.hpp"

namespace cartan::manifolds {

template <int Dim>
class Euclidean {
 public:
  static_assert(Dim >= 1);
  static constexpr int kDim = Dim;
  static constexpr int kAmbientDim = Dim;
  using Vector = Eigen::Matrix<double, Dim, 1>;
  using Point = Vector;
  using Frame = Eigen::Matrix<double, Dim, Dim>;
  using Operator = Eigen::Matrix<double, Dim, Dim>;
  /// coefficients[i] is the matrix of y -> nabla_{e_i} y, i.e. coefficients[i](k, j) = Gamma^k_ij.
  using Coefficients = std::array<Operator, Dim>;
  /// Constant coefficients (derivatives.hpp).
  static constexpr bool kPointIndependentConnection = true;

  /// The flat, torsion-free connection.
  Euclidean() : Euclidean(zero_coefficients()) {}

  /// Throws std::invalid_argument naming the entry if a coefficient is not finite.
  explicit Euclidean(const Coefficients& coefficients) : gamma_(coefficients) {
    for (int i = 0; i < Dim; ++i) require_finite(gamma_[i], "Euclidean", "coefficients[" + std::to_string(i) + "]");
    parallel_ = constant_coefficients_have_parallel_torsion_and_curvature(*this, Point::Zero());
  }

  static std::string_view name() { return "euclidean"; }
  const Coefficients& coefficients() const { return gamma_; }

  Vector christoffel(const Point&, const Vector& x, const Vector& y) const { return operator_of(x) * y; }
  Vector christoffel_derivative(const Point&, const Vector&, const Vector&, const Vector&) const {
    return Vector::Zero();
  }
  Vector frame_bracket(const Vector&, const Vector&) const { return Vector::Zero(); }
  Point step(const Point& q, const Vector& x) const { return q + x; }
  Vector difference(const Point& a, const Point& b) const { return b - a; }
  /// Along the line q + s x the transport equation y' = -Gamma(x, y) has constant coefficients.
  Operator transport_along_step(const Point&, const Vector& x) const { return Operator(-operator_of(x)).exp(); }
  Operator transport_along_step_derivative(const Point&, const Vector& x, const Vector& dx) const {
    return exp_derivative<Dim>(-operator_of(x), -operator_of(dx));
  }
  StepJacobians<Euclidean> step_jacobians(const Point&, const Vector&) const {
    return {Operator::Identity(), Operator::Identity()};
  }
  Frame tangent_basis(const Point&) const { return Frame::Identity(); }
  void validate(const Point& q, std::string_view where) const { require_finite(q, where, "point"); }
  bool has_parallel_torsion_and_curvature() const { return parallel_; }

 private:
  static Coefficients zero_coefficients() {
    Coefficients c;
    for (auto& m : c) m.setZero();
    return c;
  }
  Operator operator_of(const Vector& x) const {
    Operator m = Operator::Zero();
    for (int i = 0; i < Dim; ++i) m += x[i] * gamma_[i];
    return m;
  }

  Coefficients gamma_;
  bool parallel_ = false;
};

}  // namespace cartan::manifolds
