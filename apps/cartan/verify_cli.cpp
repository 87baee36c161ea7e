// `cartan verify FILE`: the independent checks of a `cartan solve` result (verify_command.cpp,
// docs/verify.md).
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cartan/errors.hpp"
#include "command.hpp"
#include "cartan/api/json_io.hpp"
#include "cartan/api/result_file.hpp"
#include "verify_command.hpp"

namespace cartan::cli {

namespace {

constexpr std::string_view kVerifyWhere = "cartan verify";

struct VerifyFlags {
  std::string file;
  bool json = false;
};

/// The verdict on a failed solve: its data are the solver's best iterate, which may not even be
/// valid group elements (collocation's dense output off the solution); then the failing
/// `converged` check and a note are the whole report.
verify::Report verify_failed(const nlohmann::json& j, Status status) {
  try {
    return verify(api::read_solution(j, kVerifyWhere));
  } catch (const std::invalid_argument& e) {
    return verify::unchecked_failure(status, e.what());  // the library's report, as Python's
  }
}

/// "so3 free-rigid-body, lambda = 0.5, method shooting (order 1), 101 samples, status converged".
std::string describe_result(const api::ResultRecord& record) {
  std::ostringstream out;
  if (const auto* m = std::get_if<api::ManifoldProblem>(&record.problem)) {
    out << m->manifold << " particle";
  } else {
    const auto& p = std::get<api::GroupProblem>(record.problem);
    out << p.group << " " << p.model;
    if (api::lie_kernel(p)) out << ", lambda = " << p.lambda;
    else out << ", connection " << to_string(p.connection);
  }
  const api::Result& r = record.result;
  out << ", method " << r.method << " (order " << r.order << "), " << r.samples.t.size() << " samples, status " << r.status;
  return out.str();
}

int run_verify(const VerifyFlags& flags) {
  const nlohmann::json j = io::read_json_file(flags.file, "cartan verify: FILE");
  const std::string status =
      j.is_object() && j.contains("status") && j["status"].is_string() ? j["status"].get<std::string>() : "";
  if (!status.empty() && status != "converged") {
    // An unknown status word is bad input (exit 2).
    const verify::Report report = verify_failed(j, parse_enum<Status>(status, kVerifyWhere));
    if (flags.json) std::cout << report_json(report).dump() << '\n';
    else std::cout << flags.file << ": status " << quote_input(status) << " (not converged)\n" << report.text();
    return kExitFailed;
  }
  const api::ResultRecord result = api::read_solution(j, kVerifyWhere);
  const verify::Report report = verify(result);
  if (flags.json) std::cout << report_json(report).dump() << '\n';
  else std::cout << flags.file << ": " << describe_result(result) << "\n" << report.text();
  return report.passed() ? kExitConverged : kExitFailed;
}

}  // namespace

Command add_verify_command(CLI::App& tool) {
  auto* verify = tool.add_subcommand("verify", "Check a `cartan solve` result independently of the solver");
  verify->footer(
      "Checks: boundary (terminal and initial error, |xi_N|, against the file's tol), legendre (mu = dl/dv),\n"
      "energy (1/2 v.I v + V(g) is conserved for every lambda), residual (eq:reduced-system by finite\n"
      "differences), stationarity (of the discrete transported action along random endpoint-fixed variations).\n"
      "Thresholds follow from the scheme's order and h*omega (docs/verify.md).\n"
      "Examples:\n"
      "  cartan solve --model oscillator --lambda 0.5 --T 3 --N 200 --a0 1,0,0 --aT 0,1,0 --output r.json\n"
      "  cartan verify r.json\n"
      "  cartan verify --json r.json\n"
      "A result whose status is not `converged` always fails (check `converged`), with the other checks\n"
      "run on its data where they are valid.\n"
      "Exit codes: 0 every check passed, 1 a check failed or the result is not converged, 2 bad input\n"
      "(unreadable file, invalid JSON or content).");
  auto flags = std::make_shared<VerifyFlags>();
  verify->add_option("FILE", flags->file, "result file written by `cartan solve`")->required();
  verify->add_flag("--json", flags->json, "print the report as one JSON object");
  return {verify, [flags] { return run_verify(*flags); }};
}

}  // namespace cartan::cli
