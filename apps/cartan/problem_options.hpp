#pragma once
// The problem options `cartan solve` and `cartan sweep` share: one flag per field of the problem
// (problem_fields(), problem_spec.hpp) and --problem, and the merge of a --problem file with the
// flags given on the command line (flags override the file). Each command adds its own options
// (solve: --output; sweep: the grid and the table).

#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "problem_spec.hpp"

namespace cartan::cli {

/// What the problem flags hold until the command line has been parsed. The list-valued flags are
/// kept as text (by field key) and parsed by problem_from, so that their errors name the flag.
struct ProblemFlags {
  ProblemSpec spec;
  std::string problem_file;
  std::map<std::string, std::string> lists;
};

/// Registers --problem and a flag for every problem field except output (problem_fields()) on
/// `command`, bound to `flags` (which must outlive the parse).
void add_problem_options(CLI::App& command, ProblemFlags& flags);

/// The problem the parsed command line describes: the --problem file (if any), then every flag
/// given on the command line (an option of `command` that is a problem field). Not validated:
/// call validate() on the result. Throws std::invalid_argument naming the command and the flag
/// for an unreadable file or a bad list.
ProblemSpec problem_from(const CLI::App& command, ProblemFlags& flags);

}  // namespace cartan::cli
