#pragma once
// One function per group, each in its own translation unit (they compile in parallel).

#include <pybind11/pybind11.h>

namespace cartan::python {
void bind_so3(pybind11::module_& m);
void bind_heisenberg(pybind11::module_& m);
void bind_se3(pybind11::module_& m);
void bind_se2(pybind11::module_& m);
void bind_bvp(pybind11::module_& m);  ///< solve_bvp and its dense output
void bind_manifolds(pybind11::module_& m);  ///< manifolds with a connection (Sphere, ..., Chart)
void bind_group_manifold(pybind11::module_& m);  ///< GroupManifold (any left-invariant connection)
void bind_general(pybind11::module_& m);  ///< solve_general and verify_general on those manifolds
void bind_results(pybind11::module_& m);  ///< the result file's writer and reader (the library's)
}  // namespace cartan::python
