// The Heisenberg group H3 in coordinates (a, b, c) and its harmonic oscillator (appendix
// "Nilpotent case").
#include "bind_all.hpp"
#include "bindings.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"

namespace cartan::python {

void bind_heisenberg(py::module_& m) {
  auto group = bind_all<groups::Heisenberg, Types<mechanics::H3Oscillator>, Types<mechanics::H3OscillatorHamiltonian>, Types<mechanics::H3Oscillator>>(
      m, "Heisenberg", "The Heisenberg group H3: elements are coordinates (a, b, c), [E1, E2] = E3 (ad-Heis).");
  bind_lagrangian<groups::Heisenberg, mechanics::H3Oscillator>(
      m, group, "H3Oscillator", "left", "l(g, v) = 1/2 v.I v - 1/2 (a^2 + b^2 + c^2); the paper's I is the identity.",
      inertia_init<3, true>("H3Oscillator", [](const Eigen::Matrix3d& i) { return mechanics::H3Oscillator(i); }));
  bind_hamiltonian<groups::Heisenberg, mechanics::H3OscillatorHamiltonian>(
      m, group, "H3OscillatorHamiltonian", "left", "h(g, mu) = 1/2 mu.I^-1 mu + 1/2 (a^2 + b^2 + c^2).",
      inertia_init<3, true>("H3OscillatorHamiltonian",
                            [](const Eigen::Matrix3d& i) { return mechanics::H3OscillatorHamiltonian(i); }));
}

}  // namespace cartan::python
