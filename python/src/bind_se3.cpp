// SE(3): the group (no built-in models; Lagrangians and Hamiltonians may be written in Python).
#include "bind_all.hpp"
#include "bindings.hpp"
#include "cartan/groups/se3.hpp"

namespace cartan::python {

void bind_se3(py::module_& m) {
  auto group = bind_all<groups::SE3, Types<>, Types<>, Types<>>(
      m, "SE3", "SE(3): elements are (4, 4) matrices [[R, t], [0, 1]]; algebra coordinates (rho, omega).");
  group.def_static("from_rotation_translation", [](const py::object& r, const py::object& t) {
    return to_numpy(groups::SE3::from_rotation_translation(to_eigen<Eigen::Matrix3d>(r, "SE3.from_rotation_translation", "R"),
                                                   to_eigen<Eigen::Vector3d>(t, "SE3.from_rotation_translation", "t")));
  }, py::arg("R"), py::arg("t"), "[[R, t], [0, 1]] (not validated).");
}

}  // namespace cartan::python
