// SE(2): the group and the free body in the plane (mechanics/free_body.hpp); other Lagrangians
// and Hamiltonians may be written in Python.
#include "bind_all.hpp"
#include "bindings.hpp"
#include "cartan/mechanics/free_body.hpp"

namespace cartan::python {

void bind_se2(py::module_& m) {
  auto group = bind_all<groups::SE2, Types<mechanics::SE2FreeBody>, Types<mechanics::SE2FreeBodyHamiltonian>,
                        Types<mechanics::SE2FreeBody>>(
      m, "SE2", "SE(2): elements are (3, 3) matrices [[R, t], [0, 1]]; algebra coordinates (x, y, theta).");
  bind_lagrangian<groups::SE2, mechanics::SE2FreeBody>(
      m, group, "SE2FreeBody", "left",
      "Free body in the plane l(g, v) = 1/2 v.I v, v = (x, y, theta) in the body frame; diag(m, m, J) for "
      "mass m and moment J about the centre of mass (the CLI's se2 model free-body).",
      inertia_init<3>("SE2FreeBody", [](const Eigen::Matrix3d& i) { return mechanics::SE2FreeBody(i); }));
  bind_hamiltonian<groups::SE2, mechanics::SE2FreeBodyHamiltonian>(
      m, group, "SE2FreeBodyHamiltonian", "left", "h(g, mu) = 1/2 mu.I^-1 mu on SE(2).",
      inertia_init<3>("SE2FreeBodyHamiltonian", [](const Eigen::Matrix3d& i) { return mechanics::SE2FreeBodyHamiltonian(i); }));
}

}  // namespace cartan::python
