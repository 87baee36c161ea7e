#pragma once
// Any reduced Lagrangian on a Lie group G behind one type (DESIGN.md, "mechanics: erased"):
// ErasedLagrangian<G> holds a ReducedLagrangian<G> (lagrangian.hpp) behind a shared pointer and
// forwards value, momentum, group_gradient, velocity and the second derivatives (the wrapped
// type's own `hessian` where it has one, central differences otherwise: lagrangian_hessian.hpp).
// The transported solve and verify are compiled once for it on every shipped group
// (kernels/lie_group/compiled.hpp, src/kernels/lie_group/), so that the Python module's Lagrangians and a
// user's own reuse them; the cost is one indirect call per evaluation. A wrapped model's
// HessianStructure is carried as data (hessian_structure(), which the schemes read at run time);
// its other static traits (natural or purely kinetic) are not seen through the erased type: a
// built-in model is solved as its own type.

#include <concepts>
#include <memory>
#include <utility>

#include "cartan/mechanics/lagrangian.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"

namespace cartan::mechanics {

template <groups::LieGroup G>
class ErasedLagrangian {
 public:
  using Element = groups::ElementOf<G>;
  using Tangent = groups::TangentOf<G>;
  using Covector = groups::CovectorOf<G>;

  /// Wraps `lagrangian` (copied or moved into shared, immutable storage). A type derived from
  /// this one is copied as it is (its pointer), not wrapped again.
  template <ReducedLagrangian<G> L>
    requires(!std::derived_from<L, ErasedLagrangian>)
  explicit ErasedLagrangian(L lagrangian) : impl_(std::make_shared<const Model<L>>(std::move(lagrangian))) {}

  double value(double t, const Element& g, const Tangent& v) const { return impl_->value(t, g, v); }
  Covector momentum(double t, const Element& g, const Tangent& v) const { return impl_->momentum(t, g, v); }
  Covector group_gradient(double t, const Element& g, const Tangent& v) const { return impl_->group_gradient(t, g, v); }
  Tangent velocity(double t, const Element& g, const Covector& mu) const { return impl_->velocity(t, g, mu); }
  /// The wrapped Lagrangian's second derivatives (lagrangian_hessian.hpp).
  LagrangianHessian<G> hessian(double t, const Element& g, const Tangent& v) const { return impl_->hessian(t, g, v); }
  /// The wrapped Lagrangian's structure (hessian_structure_of), which the schemes read at run time.
  RuntimeHessianStructure hessian_structure() const { return impl_->structure; }

 private:
  struct Interface {
    virtual ~Interface() = default;
    virtual double value(double t, const Element& g, const Tangent& v) const = 0;
    virtual Covector momentum(double t, const Element& g, const Tangent& v) const = 0;
    virtual Covector group_gradient(double t, const Element& g, const Tangent& v) const = 0;
    virtual Tangent velocity(double t, const Element& g, const Covector& mu) const = 0;
    virtual LagrangianHessian<G> hessian(double t, const Element& g, const Tangent& v) const = 0;
    RuntimeHessianStructure structure;
  };
  template <class L>
  struct Model final : Interface {
    explicit Model(L l) : lagrangian(std::move(l)) { this->structure = hessian_structure_of(lagrangian); }
    double value(double t, const Element& g, const Tangent& v) const override { return lagrangian.value(t, g, v); }
    Covector momentum(double t, const Element& g, const Tangent& v) const override { return lagrangian.momentum(t, g, v); }
    Covector group_gradient(double t, const Element& g, const Tangent& v) const override {
      return lagrangian.group_gradient(t, g, v);
    }
    Tangent velocity(double t, const Element& g, const Covector& mu) const override { return lagrangian.velocity(t, g, mu); }
    LagrangianHessian<G> hessian(double t, const Element& g, const Tangent& v) const override {
      return lagrangian_hessian<G>(lagrangian, t, g, v);
    }
    L lagrangian;
  };
  std::shared_ptr<const Interface> impl_;
};

}  // namespace cartan::mechanics
