// `cartan verify FILE`: the independent checks of a `cartan solve` result (verify_command.cpp,
// docs/verify.md).
#include <iostream>
#include <memory>

#include "command.hpp"
#include "json_io.hpp"
#include "result_reader.hpp"
#include "verify_command.hpp"

namespace cartan::cli {

namespace {

struct VerifyFlags {
  std::string file;
  bool json = false;
};

int run_verify(const VerifyFlags& flags) {
  const ResultFile result = read_result(read_json_file(flags.file, "cartan verify: FILE"));
  const VerifyReport report = verify(result);
  if (flags.json) {
    std::cout << report.json().dump() << '\n';
  } else {
    std::cout << flags.file << ": " << result.group << " " << result.model << ", lambda = " << result.lambda
              << ", method " << result.method << " (order " << result.order << "), " << result.t.size()
              << " samples, status " << result.status << "\n"
              << report.text();
  }
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
      "Exit codes: 0 every check passed, 1 a check failed, 2 bad input (unreadable file, invalid JSON or content).");
  auto flags = std::make_shared<VerifyFlags>();
  verify->add_option("FILE", flags->file, "result file written by `cartan solve`")->required();
  verify->add_flag("--json", flags->json, "print the report as one JSON object");
  return {verify, [flags] { return run_verify(*flags); }};
}

}  // namespace cartan::cli
