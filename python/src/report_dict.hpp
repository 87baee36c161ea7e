#pragma once
// Dict pieces shared by the Lie-group bindings (bind_solvers.hpp) and the general ones
// (bind_general.cpp): a verify::Report as the dict behind cartan.VerifyReport, and collocation's
// mesh report as result fields (python/cartan/__init__.py).

#include <optional>

#include "bindings.hpp"
#include "cartan/mechanics/check_report.hpp"
#include "cartan/principle/result.hpp"
#include "cartan/verify/verdict.hpp"

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

/// The report of mechanics::check_lagrangian as a dict (python/cartan/__init__.py, CheckReport):
/// ok, samples, text and checks, a list of dicts with CallbackCheck's fields.
inline py::dict check_report_dict(const mechanics::CheckReport& report) {
  py::list checks;
  for (const auto& c : report.checks) {
    py::dict d;
    d["callback"] = c.callback, d["reference"] = c.reference, d["checked"] = c.checked, d["ok"] = c.ok;
    d["discrepancy"] = c.discrepancy, d["reference_error"] = c.reference_error, d["threshold"] = c.threshold;
    d["sample"] = c.sample, d["at"] = c.at, d["note"] = c.note;
    checks.append(d);
  }
  py::dict d;
  d["ok"] = report.ok();
  d["samples"] = report.samples;
  d["checks"] = checks;
  d["text"] = report.text();
  return d;
}

/// The inverse: a report from such dicts (the checks that cartan.testing runs in Python), so that
/// every report is printed by CheckReport::text.
inline mechanics::CheckReport check_report_of(const std::string& title, const py::list& checks, int samples) {
  mechanics::CheckReport report;
  report.title = title;
  report.samples = samples;
  for (const auto& item : checks) {
    const py::dict d = py::reinterpret_borrow<py::dict>(item);
    mechanics::CallbackCheck c;
    c.callback = d["callback"].cast<std::string>(), c.reference = d["reference"].cast<std::string>();
    c.checked = d["checked"].cast<bool>(), c.ok = d["ok"].cast<bool>();
    c.discrepancy = d["discrepancy"].cast<double>(), c.reference_error = d["reference_error"].cast<double>();
    c.threshold = d["threshold"].cast<double>(), c.sample = d["sample"].cast<int>();
    c.at = d["at"].cast<std::string>(), c.note = d["note"].cast<std::string>();
    report.checks.push_back(c);
  }
  return report;
}

/// mesh_size and max_residual of a collocation result, None for the other methods.
inline void add_collocation_fields(py::dict& d, const std::optional<cartan::CollocationReport>& report) {
  d["mesh_size"] = report ? py::object(py::int_(report->mesh_size)) : py::object(py::none());
  d["max_residual"] = report ? py::object(py::float_(report->max_residual)) : py::object(py::none());
}

/// What every kernel's result has (ResultCore, principle/result.hpp), under Python's names: both
/// result types (cartan.SolveResult, cartan.GeneralSolveResult) read these keys.
inline void add_core_fields(py::dict& d, const cartan::ResultCore& s) {
  d["status"] = std::string(to_string(s.status));
  d["message"] = s.message;
  d["success"] = s.converged();
  d["method"] = std::string(to_string(s.method));
  d["order"] = s.order;
  d["branch"] = s.branch;
  d["terminal_error"] = s.terminal_error;
  d["xi_terminal"] = s.xi_terminal;
  d["sweeps"] = s.sweeps;
  d["residual_history"] = to_numpy(s.residual_history);
  d["solve_time"] = s.solve_time_s;
  add_collocation_fields(d, s.collocation);
}

}  // namespace cartan::python
