// libFuzzer target: the input as the words of a `cartan solve ...` command line, parsed by the
// options add_solve_command registers (CLI11: unknown flags, type conversions such as --N 1e99),
// and each word as a comma-separated number list (parse_list, as for --inertia/--g0/--a0).
// The command's action (validation and the solver) is not run; fuzz_problem_file covers the
// validation. Expected rejections: CLI::ParseError and std::invalid_argument; anything else
// escaping is reported by libFuzzer as a crash.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "cartan/api/json_io.hpp"
#include "problem_spec.hpp"

namespace {

/// The input split at whitespace, as a shell without quoting would.
std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// The tool with the solve command, built once: registering the options costs more than a parse,
/// and CLI11 clears the previous parse's state (counts, results) at the start of each parse.
struct SolveCommandLine {
  CLI::App tool{"cartan"};
  cartan::cli::Command solve = cartan::cli::add_solve_command(tool);  // owns what the options write to
  SolveCommandLine() { tool.require_subcommand(1); }
};

void parse_command_line(const std::vector<std::string>& args) {
  static SolveCommandLine command_line;
  std::vector<std::string> reversed{args.rbegin(), args.rend()};  // CLI11 consumes from the back
  reversed.push_back("solve");
  try {
    command_line.tool.parse(reversed);
  } catch (const CLI::ParseError&) {
    // expected rejection (and --help): the CLI reports it with exit code 2
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto args = words(text);
  parse_command_line(args);
  for (const auto& word : args) {
    try {
      (void)cartan::io::parse_list(word, "inertia");
    } catch (const std::invalid_argument&) {
      // expected rejection
    }
  }
  return 0;
}
