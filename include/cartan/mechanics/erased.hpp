#pragma once
// Any Lagrangian behind one type (DESIGN.md, "mechanics: erased"), once for both kernels:
// Erased<Terms> holds a Lagrangian behind a shared pointer and forwards value, momentum, velocity,
// the first derivative in the point and the second derivatives (the wrapped type's own `hessian`
// where it has one, central differences otherwise). Terms says in which kernel's words:
//   mechanics::ReducedTerms<G> (erased_lagrangian.hpp): a ReducedLagrangian<G>, read as
//     group_gradient(t, g, v) and hessian(t, g, v): mechanics::ErasedLagrangian<G>;
//   general::ManifoldTerms<M> (manifold_erased_lagrangian.hpp): a ManifoldLagrangian<M>,
//     read as point_gradient(t, q, v), hessian(manifold, t, q, v) and has_hessian():
//     general::ErasedLagrangian<M>.
// The other kernel's names are declared but constrained away, so that a check for a member
// (lagrangian_hessian, check_lagrangian, the concepts) sees each type as its kernel's.
// The solves and verifiers are compiled once for it on every shipped group and manifold
// (kernels/lie_group/compiled.hpp, kernels/manifold/compiled.hpp), so that the CLI, the Python
// module and a user's own Lagrangian reuse them; the cost is one indirect call per evaluation
// (bench/README.md, "Build time"). A wrapped model's HessianStructure is carried as data
// (hessian_structure(), which the schemes read at run time); its other static traits (natural or
// purely kinetic) are not seen through the erased type: a built-in model is solved as its own type.
//
// Terms supplies, as static members:
//   kOnGroup                      true: the group's names; false: the manifold's
//   Types                         TermTypes<Space, Point, Velocity, Momentum, Gradient, Hessian>
//   wraps<L>                      whether L is a Lagrangian in these terms (the kernel's concept)
//   has_hessian<L>                whether L has its own hessian
//   gradient(l, t, q, v)          l's first derivative in the point
//   hessian(l, space, t, q, v)    l's second derivatives (space: null on a group, unused)

#include <concepts>
#include <memory>
#include <utility>

#include "cartan/mechanics/lagrangian_hessian.hpp"

namespace cartan::mechanics {

/// The types a Terms names (its member Types), in one line per kernel.
template <class SpaceType, class PointType, class VelocityType, class MomentumType, class GradientType, class HessianType>
struct TermTypes {
  using Space = SpaceType;
  using Point = PointType;
  using Velocity = VelocityType;
  using Momentum = MomentumType;
  using Gradient = GradientType;
  using Hessian = HessianType;
};

template <class Terms>
class Erased {
 public:
  using Space = typename Terms::Types::Space;
  using Point = typename Terms::Types::Point;
  using Velocity = typename Terms::Types::Velocity;
  using Momentum = typename Terms::Types::Momentum;
  using Gradient = typename Terms::Types::Gradient;
  using Hessian = typename Terms::Types::Hessian;

  /// Wraps `lagrangian` (copied or moved into shared, immutable storage). A type derived from
  /// this one (python/src/bind_solvers.hpp) is copied as it is (its pointer), not wrapped again.
  template <class L>
    requires(Terms::template wraps<L> && !std::derived_from<L, Erased>)
  explicit Erased(L lagrangian) : impl_(std::make_shared<const Model<L>>(std::move(lagrangian))) {}

  double value(double t, const Point& q, const Velocity& v) const { return impl_->value(t, q, v); }
  Momentum momentum(double t, const Point& q, const Velocity& v) const { return impl_->momentum(t, q, v); }
  Velocity velocity(double t, const Point& q, const Momentum& mu) const { return impl_->velocity(t, q, mu); }
  Gradient group_gradient(double t, const Point& g, const Velocity& v) const requires(Terms::kOnGroup) {
    return impl_->gradient(t, g, v);
  }
  Gradient point_gradient(double t, const Point& q, const Velocity& v) const requires(!Terms::kOnGroup) {
    return impl_->gradient(t, q, v);
  }
  /// The wrapped Lagrangian's second derivatives (lagrangian_hessian.hpp or manifold_lagrangian_hessian.hpp).
  Hessian hessian(double t, const Point& g, const Velocity& v) const requires(Terms::kOnGroup) {
    return impl_->hessian(nullptr, t, g, v);
  }
  Hessian hessian(const Space& manifold, double t, const Point& q, const Velocity& v) const requires(!Terms::kOnGroup) {
    return impl_->hessian(&manifold, t, q, v);
  }
  /// Whether the wrapped Lagrangian has its own `hessian` (else hessian() differences it): what
  /// general::check_lagrangian checks.
  bool has_hessian() const requires(!Terms::kOnGroup) { return impl_->own_hessian; }
  /// The wrapped Lagrangian's structure (hessian_structure_of; a point gradient read as the group
  /// gradient), which the schemes read at run time.
  RuntimeHessianStructure hessian_structure() const { return impl_->structure; }
  /// Whether the wrapped Lagrangian does not depend on the orthonormal frame (frame_invariant_of).
  bool frame_invariant() const { return impl_->frame_invariant; }

 private:
  struct Interface {
    virtual ~Interface() = default;
    virtual double value(double t, const Point& q, const Velocity& v) const = 0;
    virtual Momentum momentum(double t, const Point& q, const Velocity& v) const = 0;
    virtual Velocity velocity(double t, const Point& q, const Momentum& mu) const = 0;
    virtual Gradient gradient(double t, const Point& q, const Velocity& v) const = 0;
    virtual Hessian hessian(const Space* space, double t, const Point& q, const Velocity& v) const = 0;
    RuntimeHessianStructure structure;
    bool own_hessian = false;
    bool frame_invariant = false;
  };
  template <class L>
  struct Model final : Interface {
    explicit Model(L l) : lagrangian(std::move(l)) {
      this->structure = mechanics::hessian_structure_of(lagrangian);
      this->own_hessian = Terms::template has_hessian<L>;
      this->frame_invariant = mechanics::frame_invariant_of(lagrangian);
    }
    double value(double t, const Point& q, const Velocity& v) const override { return lagrangian.value(t, q, v); }
    Momentum momentum(double t, const Point& q, const Velocity& v) const override { return lagrangian.momentum(t, q, v); }
    Velocity velocity(double t, const Point& q, const Momentum& mu) const override { return lagrangian.velocity(t, q, mu); }
    Gradient gradient(double t, const Point& q, const Velocity& v) const override {
      return Terms::gradient(lagrangian, t, q, v);
    }
    Hessian hessian(const Space* space, double t, const Point& q, const Velocity& v) const override {
      return Terms::hessian(lagrangian, space, t, q, v);
    }
    L lagrangian;
  };
  std::shared_ptr<const Interface> impl_;
};

}  // namespace cartan::mechanics
