#pragma once
// Any Lagrangian of the general problem behind one type per manifold (DESIGN.md, "mechanics:
// erased"): ErasedLagrangian<M> holds a ManifoldLagrangian<M> (lagrangian.hpp) behind a shared
// pointer and forwards value, momentum, velocity, point_gradient and the second derivatives
// (the wrapped type's own `hessian` where it has one, central differences otherwise:
// lagrangian_hessian.hpp). The general solve and verify are compiled once for it on every shipped
// manifold (compiled.hpp, src/kernels/manifold/), so that the CLI, the Python module and a user's own
// Lagrangian reuse them; the cost is one indirect call per evaluation (bench/README.md, "Build time").

#include <concepts>
#include <memory>
#include <utility>

#include "cartan/kernels/manifold/lagrangian.hpp"
#include "cartan/kernels/manifold/lagrangian_hessian.hpp"
#include "cartan/kernels/manifold/problem.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M>
class ErasedLagrangian {
 public:
  using Point = manifolds::PointOf<M>;
  using Vector = manifolds::VectorOf<M>;
  using Components = manifolds::ComponentsOf<M>;

  /// Wraps `lagrangian` (copied or moved into shared, immutable storage).
  template <ManifoldLagrangian<M> L>
    requires(!std::same_as<L, ErasedLagrangian>)
  explicit ErasedLagrangian(L lagrangian) : impl_(std::make_shared<const Model<L>>(std::move(lagrangian))) {}

  double value(double t, const Point& q, const Components& v) const { return impl_->value(t, q, v); }
  Components momentum(double t, const Point& q, const Components& v) const { return impl_->momentum(t, q, v); }
  Components velocity(double t, const Point& q, const Components& mu) const { return impl_->velocity(t, q, mu); }
  Vector point_gradient(double t, const Point& q, const Components& v) const { return impl_->point_gradient(t, q, v); }
  /// The wrapped Lagrangian's second derivatives (lagrangian_hessian.hpp).
  LagrangianHessian<M> hessian(const M& manifold, double t, const Point& q, const Components& v) const {
    return impl_->hessian(manifold, t, q, v);
  }
  /// Whether the wrapped Lagrangian has its own `hessian` (else hessian() differences it): what
  /// check_lagrangian checks.
  bool has_hessian() const { return impl_->has_hessian(); }
  /// The wrapped Lagrangian's structure (mechanics::hessian_structure_of; point gradient read as
  /// the group gradient), which the Lie-group kernel's scheme reads at run time.
  mechanics::RuntimeHessianStructure hessian_structure() const { return impl_->structure; }

 private:
  struct Interface {
    virtual ~Interface() = default;
    virtual double value(double t, const Point& q, const Components& v) const = 0;
    virtual Components momentum(double t, const Point& q, const Components& v) const = 0;
    virtual Components velocity(double t, const Point& q, const Components& mu) const = 0;
    virtual Vector point_gradient(double t, const Point& q, const Components& v) const = 0;
    virtual LagrangianHessian<M> hessian(const M& manifold, double t, const Point& q, const Components& v) const = 0;
    virtual bool has_hessian() const = 0;
    mechanics::RuntimeHessianStructure structure;
  };
  template <class L>
  struct Model final : Interface {
    explicit Model(L l) : lagrangian(std::move(l)) { this->structure = mechanics::hessian_structure_of(lagrangian); }
    double value(double t, const Point& q, const Components& v) const override { return lagrangian.value(t, q, v); }
    Components momentum(double t, const Point& q, const Components& v) const override {
      return lagrangian.momentum(t, q, v);
    }
    Components velocity(double t, const Point& q, const Components& mu) const override {
      return lagrangian.velocity(t, q, mu);
    }
    Vector point_gradient(double t, const Point& q, const Components& v) const override {
      return lagrangian.point_gradient(t, q, v);
    }
    LagrangianHessian<M> hessian(const M& manifold, double t, const Point& q, const Components& v) const override {
      return lagrangian_hessian(manifold, lagrangian, t, q, v);
    }
    bool has_hessian() const override {
      return requires(const L& l, const M& m, double t, const Point& q, const Components& v) { l.hessian(m, t, q, v); };
    }
    L lagrangian;
  };
  std::shared_ptr<const Interface> impl_;
};

/// The problem of the compiled solve on M (compiled.hpp): any Lagrangian behind the erased type.
template <manifolds::ManifoldWithConnection M>
using ErasedProblem = GeneralProblem<M, ErasedLagrangian<M>>;

/// `problem` with its Lagrangian behind the erased type (for the compiled solvers).
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
ErasedProblem<M> erased(const GeneralProblem<M, L>& problem) {
  return {problem.manifold, ErasedLagrangian<M>(problem.lagrangian), problem.T, problem.N, problem.q0, problem.qT,
          problem.frame0};
}

}  // namespace cartan::general
