// libFuzzer target: the bytes of a `cartan verify FILE` result file through the command's own
// path, parse_json -> read_result -> verify (the checks) -> the report's text and JSON. Expected
// rejections are std::invalid_argument; any other exception escapes and is reported by libFuzzer
// as a crash, as are sanitizer findings, leaks, timeouts and huge allocations. A report must hold
// one entry per check with finite, non-negative thresholds (oracle for silent nonsense).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "json_io.hpp"
#include "result_reader.hpp"
#include "verify_command.hpp"

namespace {

void require(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "fuzz_result_reader: invariant violated: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const cartan::cli::ResultFile result = cartan::cli::read_result(cartan::cli::parse_json(text, "cartan verify: FILE"));
    require(result.t.size() >= 2 && result.g.rows() == result.t.size(), "validated sizes");
    const cartan::verify::Report report = cartan::cli::verify(result);
    require(!report.checks.empty(), "a report has checks");
    for (const auto& check : report.checks) {
      require(std::isfinite(check.threshold) && check.threshold >= 0, "thresholds are finite and non-negative");
    }
    require(!report.text().empty() && cartan::cli::report_json(report).is_object(), "the report renders");
  } catch (const std::invalid_argument&) {
    // expected rejection of bad input: the CLI reports it with exit code 2
  }
  return 0;
}
