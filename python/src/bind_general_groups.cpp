// The general solve on the four group manifolds (general_binding.hpp), in a unit of its own.

#include "general_binding.hpp"

namespace cartan::python::general_binding {

template py::dict solve_on(const OnGroup<groups::SO3>&, const GeneralRequest&, ChartCallbacks*);
template py::dict verify_on(const OnGroup<groups::SO3>&, const GeneralRequest&, const py::object&,
                            ChartCallbacks*);
template py::dict solve_on(const OnGroup<groups::Heisenberg>&, const GeneralRequest&, ChartCallbacks*);
template py::dict verify_on(const OnGroup<groups::Heisenberg>&, const GeneralRequest&, const py::object&,
                            ChartCallbacks*);
template py::dict solve_on(const OnGroup<groups::SE2>&, const GeneralRequest&, ChartCallbacks*);
template py::dict verify_on(const OnGroup<groups::SE2>&, const GeneralRequest&, const py::object&,
                            ChartCallbacks*);
template py::dict solve_on(const OnGroup<groups::SE3>&, const GeneralRequest&, ChartCallbacks*);
template py::dict verify_on(const OnGroup<groups::SE3>&, const GeneralRequest&, const py::object&,
                            ChartCallbacks*);

}  // namespace cartan::python::general_binding
