#pragma once
// A verify::Report as the dict behind cartan.VerifyReport (python/cartan/__init__.py), for the
// Lie-group verifier (bind_solvers.hpp) and the general one (bind_general.cpp).

#include "bindings.hpp"
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

}  // namespace cartan::python
