// The cartan command-line tool. `cartan <command> --help` lists each command's options. Exit codes:
// 0 success, 1 the solver failed (the JSON result is still written), 2 bad input (one line on stderr),
// 130 interrupted by Ctrl-C (solve, sweep, merge: nothing written; output.hpp).
#include <iostream>
#include <string>

#include "cartan/errors.hpp"
#include "command.hpp"
#include "output.hpp"

int main(int argc, char** argv) {
  using namespace cartan::cli;
  const InterruptScope scope;  // from here on Ctrl-C raises a flag (output.hpp): no command is cut short
  CLI::App tool{"cartan: geometric mechanics on Lie groups with invariant connections"};
  tool.require_subcommand(1);
  tool.set_version_flag("--version", std::string("cartan ") + CARTAN_VERSION);  // the project's VERSION (CMake)
  const std::vector<Command> commands = {add_solve_command(tool), add_sweep_command(tool), add_merge_command(tool),
                                         add_verify_command(tool)};
  if (argc >= 2 && argv[1][0] != '-') {  // CLI11 would say only "A subcommand is required"
    std::string names;
    bool known = false;
    for (const auto& c : commands) {
      known = known || c.app->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + c.app->get_name();
    }
    if (!known) {
      std::cerr << "cartan: " << cartan::quote_input(argv[1]) << " is not a command (commands: " << names
                << "; see cartan --help)\n";
      return kExitBadInput;
    }
  }

  try {
    tool.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return tool.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return tool.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string help = "cartan --help";
    for (const auto& c : commands) {
      if (c.app->parsed()) help = "cartan " + c.app->get_name() + " --help";
    }
    std::cerr << "cartan: " << e.what() << " (see " << help << ")\n";
    return kExitBadInput;
  }
  try {
    for (const auto& c : commands) {
      if (!c.app->parsed()) continue;
      if (interrupted()) return exit_interrupted("cartan " + c.app->get_name());
      return c.run();
    }
    return kExitBadInput;  // unreachable: require_subcommand(1)
  } catch (const std::invalid_argument& e) {
    std::cerr << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cartan: internal error: " << e.what() << '\n';
    return kExitFailed;
  }
}
