// SO(3): the group, the free rigid body and the SO(3) oscillator (left-reduced, the paper's
// models), the spatial (right-reduced) rigid body, and SO(3)-specific helpers.
#include "bind_all.hpp"
#include "bindings.hpp"
#include "cartan/mechanics/rigid_body.hpp"

namespace cartan::python {

void bind_so3(py::module_& m) {
  auto group = bind_all<groups::SO3, Types<mechanics::RigidBody, mechanics::SO3Oscillator, mechanics::SpatialRigidBody>,
                        Types<mechanics::RigidBodyHamiltonian, mechanics::SO3OscillatorHamiltonian, mechanics::SpatialRigidBodyHamiltonian>,
                        Types<mechanics::RigidBody, mechanics::SO3Oscillator>>(
      m, "SO3", "SO(3): elements are (3, 3) rotation matrices, hat(v) w = v x w (docs/conventions.md).");
  group.def_static("minimal_rotation", [](const py::object& a, const py::object& b) {
    return to_numpy(groups::SO3::minimal_rotation(to_eigen<Eigen::Vector3d>(a, "SO3.minimal_rotation", "a"),
                                          to_eigen<Eigen::Vector3d>(b, "SO3.minimal_rotation", "b")));
  }, py::arg("a"), py::arg("b"), "The rotation taking the direction of a to that of b about a x b (the paper's gT).");
  group.def_static("from_matrix", [](const py::object& r, double tolerance) {
    return to_numpy(groups::SO3::from_matrix(to_eigen<Eigen::Matrix3d>(r, "SO3.from_matrix", "r"), tolerance));
  }, py::arg("r"), py::arg("tolerance") = groups::SO3::kDefaultTolerance,
     "Validates a near-rotation (within tolerance) and returns the nearest rotation.");

  bind_lagrangian<groups::SO3, mechanics::RigidBody>(m, group, "RigidBody", "left", "Free rigid body l(g, v) = 1/2 v.I v (body frame).",
                                  inertia_init<3>("RigidBody", [](const Eigen::Matrix3d& i) { return mechanics::RigidBody(i); }));
  bind_lagrangian<groups::SO3, mechanics::SO3Oscillator>(
      m, group, "SO3Oscillator", "left",
      "Harmonic oscillator l(g, v) = 1/2 v.I v - 1/2 (3 - tr g), restoring force zeta = -vee(Skew g) "
      "(docs/paper-notes.md#erratum-1).",
      inertia_init<3>("SO3Oscillator", [](const Eigen::Matrix3d& i) { return mechanics::SO3Oscillator(i); }));
  bind_lagrangian<groups::SO3, mechanics::SpatialRigidBody>(
      m, group, "SpatialRigidBody", "right", "The free rigid body right-reduced (spatial velocity); for eq:EP-right.",
      inertia_init<3>("SpatialRigidBody", [](const Eigen::Matrix3d& i) { return mechanics::SpatialRigidBody(mechanics::RigidBody(i)); }));
  bind_hamiltonian<groups::SO3, mechanics::RigidBodyHamiltonian>(
      m, group, "RigidBodyHamiltonian", "left", "h(g, mu) = 1/2 mu.I^-1 mu.",
      inertia_init<3>("RigidBodyHamiltonian", [](const Eigen::Matrix3d& i) { return mechanics::RigidBodyHamiltonian(i); }));
  bind_hamiltonian<groups::SO3, mechanics::SO3OscillatorHamiltonian>(
      m, group, "SO3OscillatorHamiltonian", "left", "h(g, mu) = 1/2 mu.I^-1 mu + 1/2 (3 - tr g).",
      inertia_init<3>("SO3OscillatorHamiltonian", [](const Eigen::Matrix3d& i) { return mechanics::SO3OscillatorHamiltonian(i); }));
  bind_hamiltonian<groups::SO3, mechanics::SpatialRigidBodyHamiltonian>(
      m, group, "SpatialRigidBodyHamiltonian", "right", "The free rigid body Hamiltonian right-reduced; for eq:LP-right.",
      inertia_init<3>("SpatialRigidBodyHamiltonian", 
          [](const Eigen::Matrix3d& i) { return mechanics::SpatialRigidBodyHamiltonian(mechanics::RigidBodyHamiltonian(i)); }));
}

}  // namespace cartan::python
