#pragma once
// The harmonic oscillator on the Heisenberg group H3 (paper appendix "Nilpotent case"),
// left-reduced: l(g, v) = 1/2 |v|^2 - V(g), V(a, b, c) = 1/2 (a^2 + b^2 + c^2),
// h(g, mu) = 1/2 |mu|^2 + V(g).

#include "cartan/heisenberg.hpp"
#include "cartan/models/natural_system.hpp"

namespace cartan {

/// V(a, b, c) = 1/2 (a^2 + b^2 + c^2). Left gradient from (left-Heis): d(L_g)_e w =
/// (w1, w2, w3 + a w2), so dV . w = (a, b, c) . (w1, w2, w3 + a w2), i.e.
/// dV = (a, b + a c, c). The oscillator's zeta = -dV.
struct HeisenbergQuadraticPotential {
  double value(const Heisenberg::Element& g) const { return g.squaredNorm() / 2; }
  Heisenberg::Tangent left_gradient(const Heisenberg::Element& g) const {
    return {g[0], g[1] + g[0] * g[2], g[2]};
  }
  /// g exp(e w) moves the coordinates by e (w1, w2, w3 + a w2) (left-Heis), so
  /// d dV = (w1, w2 + c w1 + a (w3 + a w2), w3 + a w2).
  Heisenberg::AlgebraMatrix left_hessian(const Heisenberg::Element& g) const {
    const double a = g[0], c = g[2];
    Heisenberg::AlgebraMatrix h;
    h << 1, 0, 0,     //
        c, 1 + a * a, a,  //
        0, a, 1;
    return h;
  }
};

using H3Oscillator = NaturalLagrangian<Heisenberg, HeisenbergQuadraticPotential>;
using H3OscillatorHamiltonian = NaturalHamiltonian<Heisenberg, HeisenbergQuadraticPotential>;

/// The paper's H3 oscillator has unit inertia.
inline H3Oscillator h3_oscillator() { return H3Oscillator(Heisenberg::AlgebraMatrix::Identity()); }
inline H3OscillatorHamiltonian h3_oscillator_hamiltonian() {
  return H3OscillatorHamiltonian(Heisenberg::AlgebraMatrix::Identity());
}

}  // namespace cartan
