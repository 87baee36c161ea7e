#pragma once
// Dict pieces shared by the Lie-group bindings (bind_solvers.hpp) and the general ones
// (bind_general.cpp): a verify::Report as the dict behind cartan.VerifyReport, and collocation's
// mesh report as result fields (python/cartan/__init__.py).

#include <optional>

#include "bindings.hpp"
#include "cartan/transported/solution.hpp"
#include "cartan/verify/report.hpp"

namespace cartan::python {

/// The report of verify::verify_trajectory as a dict (python/cartan/__init__.py, VerifyReport).
inline py::dict report_dict(const verify::Report& report) {
  py::list checks;
  for (const auto& c : report.checks) {
    py::dict d;
    d["name"] = c.name, d["figure"] = c.figure, d["threshold"] = c.threshold, d["result"] = c.verdict();
    d["note"] = c.note;
    checks.append(d);
  }
  py::dict d;
  d["passed"] = report.passed();
  d["verdict"] = report.passed() ? "PASS" : "FAIL";
  d["resolution"] = report.resolution;
  d["order"] = report.order;
  d["amplification"] = report.amplification;
  d["checks"] = checks;
  d["text"] = report.text();
  return d;
}

/// mesh_size and max_residual of a collocation result, None for the other methods.
inline void add_collocation_fields(py::dict& d, const std::optional<transported::CollocationReport>& report) {
  d["mesh_size"] = report ? py::object(py::int_(report->mesh_size)) : py::object(py::none());
  d["max_residual"] = report ? py::object(py::float_(report->max_residual)) : py::object(py::none());
}

}  // namespace cartan::python
