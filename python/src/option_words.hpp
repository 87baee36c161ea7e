#pragma once
// The option fields of the request classes (cartan.solve's _SolveRequest, cartan.solve_general's
// _GeneralRequest): the library's OptionWords (principle/options.hpp), bound once. Python sets
// only the keywords it was given, so the library's defaults stand for the others.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "cartan/principle/options.hpp"

namespace cartan::python {

/// Binds every field of OptionWords on `c`, a class_ of OptionWords or of a type derived from it.
template <class Class>
Class& def_option_words(Class& c) {
  return c.def_readwrite("method", &OptionWords::method)
      .def_readwrite("continuation", &OptionWords::continuation)
      .def_readwrite("order", &OptionWords::order)
      .def_readwrite("tol", &OptionWords::tol)
      .def_readwrite("max_iterations", &OptionWords::max_iterations)
      .def_readwrite("segments", &OptionWords::segments)
      .def_readwrite("lambda_start", &OptionWords::lambda_start)
      .def_readwrite("samples", &OptionWords::samples)
      .def_readwrite("max_nodes", &OptionWords::max_nodes)
      .def_readwrite("time_limit", &OptionWords::time_limit);
}

}  // namespace cartan::python
