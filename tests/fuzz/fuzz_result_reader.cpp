// libFuzzer target: the bytes of a `cartan verify FILE` result file through the command's own
// path, parse_json -> api::read_solution -> verify (the checks) -> the report's text and JSON. Expected
// rejections are std::invalid_argument; any other exception escapes and is reported by libFuzzer
// as a crash, as are sanitizer findings, leaks, timeouts and huge allocations. A report must hold
// one entry per check with finite, non-negative thresholds (oracle for silent nonsense).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "cartan/api/json_io.hpp"
#include "cartan/api/result_file.hpp"
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
    const cartan::api::ResultRecord result = cartan::api::read_solution(cartan::io::parse_json(text, "cartan verify: FILE"), "cartan verify");
    const cartan::api::Samples& x = result.result.samples;
    require(x.t.size() >= 2 && x.points.rows() == x.t.size() && x.aux.rows() == x.t.size(), "validated sizes");
    // What the library writes of it, it reads back as the same record.
    const std::string written = cartan::api::result_text(result);
    require(cartan::api::result_text(cartan::api::read_result_text(written, "fuzz")) == written,
            "the writer and the reader agree");
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
