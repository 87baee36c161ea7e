// SE(2): the group (no built-in models; Lagrangians and Hamiltonians may be written in Python).
#include "bind_all.hpp"
#include "bindings.hpp"
#include "cartan/groups/se2.hpp"

namespace cartan::python {

void bind_se2(py::module_& m) {
  bind_all<groups::SE2, Types<>, Types<>, Types<>>(
      m, "SE2", "SE(2): elements are (3, 3) matrices [[R, t], [0, 1]]; algebra coordinates (x, y, theta).");
}

}  // namespace cartan::python
