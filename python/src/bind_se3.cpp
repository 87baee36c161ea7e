// SE(3): the group and the free body in space (mechanics/free_body.hpp); other Lagrangians and
// Hamiltonians may be written in Python.
#include "bind_all.hpp"
#include "bindings.hpp"
#include "cartan/mechanics/free_body.hpp"

namespace cartan::python {

void bind_se3(py::module_& m) {
  auto group = bind_all<groups::SE3, Types<mechanics::SE3FreeBody>, Types<mechanics::SE3FreeBodyHamiltonian>,
                        Types<mechanics::SE3FreeBody>>(
      m, "SE3", "SE(3): elements are (4, 4) matrices [[R, t], [0, 1]]; algebra coordinates (rho, omega).");
  group.def_static("from_rotation_translation", [](const py::object& r, const py::object& t) {
    return to_numpy(groups::SE3::from_rotation_translation(to_eigen<Eigen::Matrix3d>(r, "SE3.from_rotation_translation", "R"),
                                                   to_eigen<Eigen::Vector3d>(t, "SE3.from_rotation_translation", "t")));
  }, py::arg("R"), py::arg("t"), "[[R, t], [0, 1]] (not validated).");
  using Inertia6 = Eigen::Matrix<double, 6, 6>;
  bind_lagrangian<groups::SE3, mechanics::SE3FreeBody>(
      m, group, "SE3FreeBody", "left",
      "Free body in space l(g, v) = 1/2 v.I v, v = (rho, omega) in the body frame; diag(m, m, m, J1, J2, J3) "
      "about the centre of mass along principal axes (the CLI's se3 model free-body).",
      inertia_init<6>("SE3FreeBody", [](const Inertia6& i) { return mechanics::SE3FreeBody(i); }));
  bind_hamiltonian<groups::SE3, mechanics::SE3FreeBodyHamiltonian>(
      m, group, "SE3FreeBodyHamiltonian", "left", "h(g, mu) = 1/2 mu.I^-1 mu on SE(3).",
      inertia_init<6>("SE3FreeBodyHamiltonian", [](const Inertia6& i) { return mechanics::SE3FreeBodyHamiltonian(i); }));
}

}  // namespace cartan::python
