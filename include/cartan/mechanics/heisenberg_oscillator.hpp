#pragma once
// The harmonic oscillator on the Heisenberg group H3 (paper appendix "Nilpotent case"),
// left-reduced: l(g, v) = 1/2 |v|^2 - V(g), V(a, b, c) = 1/2 (a^2 + b^2 + c^2),
// h(g, mu) = 1/2 |mu|^2 + V(g).

#include "cartan/groups/heisenberg.hpp"
#include "cartan/mechanics/natural_system.hpp"

namespace cartan::mechanics {

/// V(a, b, c) = 1/2 (a^2 + b^2 + c^2). Left gradient from (left-Heis): d(L_g)_e w =
/// (w1, w2, w3 + a w2), so dV . w = (a, b, c) . (w1, w2, w3 + a w2), i.e.
/// dV = (a, b + a c, c). The oscillator's zeta = -dV.
struct HeisenbergQuadraticPotential {
  double value(const groups::Heisenberg::Element& g) const { return g.squaredNorm() / 2; }
  groups::Heisenberg::Tangent left_gradient(const groups::Heisenberg::Element& g) const {
    return {g[0], g[1] + g[0] * g[2], g[2]};
  }
  /// g exp(e w) moves the coordinates by e (w1, w2, w3 + a w2) (left-Heis), so
  /// d dV = (w1, w2 + c w1 + a (w3 + a w2), w3 + a w2).
  groups::Heisenberg::AlgebraMatrix left_hessian(const groups::Heisenberg::Element& g) const {
    const double a = g[0], c = g[2];
    groups::Heisenberg::AlgebraMatrix h;
    h << 1, 0, 0,     //
        c, 1 + a * a, a,  //
        0, a, 1;
    return h;
  }
};

using H3Oscillator = NaturalLagrangian<groups::Heisenberg, HeisenbergQuadraticPotential>;
using H3OscillatorHamiltonian = NaturalHamiltonian<groups::Heisenberg, HeisenbergQuadraticPotential>;

/// The paper's H3 oscillator has unit inertia.
inline H3Oscillator h3_oscillator() { return H3Oscillator(groups::Heisenberg::AlgebraMatrix::Identity()); }
inline H3OscillatorHamiltonian h3_oscillator_hamiltonian() {
  return H3OscillatorHamiltonian(groups::Heisenberg::AlgebraMatrix::Identity());
}

}  // namespace cartan::mechanics
