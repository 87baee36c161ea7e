#pragma once
// The right-reduced (spatial) form of a left-reduced model (appendix "Right formalism").
// With v_- = g^{-1} g' = Ad_{g^-1} v_+ and mu_- = d(L_g)^*p = Ad_g^T mu_+:
//   l_+(t, g, v) = l_-(t, g, Ad_{g^-1} v),        h_+(t, g, mu) = h_-(t, g, Ad_g^T mu),
//   momentum  mu_+ = Ad_{g^-1}^T mu_-,             velocity  v_+ = Ad_g v_-.
// Right-trivialised group gradients (zeta . w = d/de f(exp(e w) g)): write exp(e w) g =
// g exp(e Ad_{g^-1} w) for the first slot; in the second, d/de Ad_{(exp(e w) g)^-1} v =
// Ad_{g^-1} ad_v w and d/de Ad_{exp(e w) g}^T mu = Ad_g^T ad_w^T mu. Pairing with mu_- (resp. v_-):
//   zeta_{l+} = Ad_{g^-1}^T zeta_{l-} + ad*_{v_+} mu_+,
//   zeta_{h+} = Ad_{g^-1}^T zeta_{h-} - ad*_{v_+} mu_+.
// For the free rigid body zeta_{l-} = 0, so zeta_{l+} = ad*_v mu and (eq:EP-right) reduces to
// conservation of the spatial momentum, mu_+' = 0.

#include <utility>

#include "cartan/groups/group.hpp"
#include "cartan/mechanics/lagrangian.hpp"

namespace cartan::mechanics {

template <groups::LieGroup G, ReducedLagrangian<G> L>
class RightReducedLagrangian {
 public:
  explicit RightReducedLagrangian(L left) : left_(std::move(left)) {}

  double value(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return left_.value(t, g, body(g, v));
  }
  groups::CovectorOf<G> momentum(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    return G::Ad(G::inverse(g)).transpose() * groups::CovectorOf<G>(left_.momentum(t, g, body(g, v)));
  }
  groups::CovectorOf<G> group_gradient(double t, const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) const {
    const groups::AlgebraMatrixOf<G> ad_inverse_transpose = G::Ad(G::inverse(g)).transpose();
    const groups::TangentOf<G> v_body = body(g, v);
    const groups::CovectorOf<G> mu = ad_inverse_transpose * groups::CovectorOf<G>(left_.momentum(t, g, v_body));
    return ad_inverse_transpose * groups::CovectorOf<G>(left_.group_gradient(t, g, v_body)) + groups::coad<G>(v, mu);
  }
  groups::TangentOf<G> velocity(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return G::Ad(g) * groups::TangentOf<G>(left_.velocity(t, g, G::Ad(g).transpose() * mu));
  }

  const L& left_reduced() const { return left_; }

 private:
  static groups::TangentOf<G> body(const groups::ElementOf<G>& g, const groups::TangentOf<G>& v) { return G::Ad(G::inverse(g)) * v; }
  L left_;
};

template <groups::LieGroup G, ReducedHamiltonian<G> H>
class RightReducedHamiltonian {
 public:
  explicit RightReducedHamiltonian(H left) : left_(std::move(left)) {}

  double value(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return left_.value(t, g, body(g, mu));
  }
  groups::TangentOf<G> velocity(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    return G::Ad(g) * groups::TangentOf<G>(left_.velocity(t, g, body(g, mu)));
  }
  groups::CovectorOf<G> group_gradient(double t, const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) const {
    const groups::CovectorOf<G> mu_body = body(g, mu);
    const groups::TangentOf<G> v = G::Ad(g) * groups::TangentOf<G>(left_.velocity(t, g, mu_body));
    return G::Ad(G::inverse(g)).transpose() * groups::CovectorOf<G>(left_.group_gradient(t, g, mu_body)) - groups::coad<G>(v, mu);
  }

  const H& left_reduced() const { return left_; }

 private:
  static groups::CovectorOf<G> body(const groups::ElementOf<G>& g, const groups::CovectorOf<G>& mu) { return G::Ad(g).transpose() * mu; }
  H left_;
};

template <groups::LieGroup G, ReducedLagrangian<G> L>
RightReducedLagrangian<G, L> right_reduced_lagrangian(L left) {
  return RightReducedLagrangian<G, L>(std::move(left));
}

template <groups::LieGroup G, ReducedHamiltonian<G> H>
RightReducedHamiltonian<G, H> right_reduced_hamiltonian(H left) {
  return RightReducedHamiltonian<G, H>(std::move(left));
}

}  // namespace cartan::mechanics
