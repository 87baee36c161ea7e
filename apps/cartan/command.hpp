#pragma once
// One `cartan` subcommand: the CLI11 sub-app that holds its options, and the action to run once
// the command line has been parsed. Each subcommand lives in its own <name>_cli.cpp and is added
// to the tool in main.cpp. Actions throw std::invalid_argument on bad input (exit code 2, the
// message on stderr) and return the exit code otherwise.

#include <CLI/CLI.hpp>
#include <functional>

namespace cartan::cli {

inline constexpr int kExitConverged = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInterrupted = 130;  ///< 128 + SIGINT, as shells report it

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// `cartan solve` (solve_cli.cpp).
Command add_solve_command(CLI::App& tool);

/// `cartan sweep` (sweep_cli.cpp).
Command add_sweep_command(CLI::App& tool);

/// `cartan merge` (merge_cli.cpp).
Command add_merge_command(CLI::App& tool);

/// `cartan verify` (verify_cli.cpp).
Command add_verify_command(CLI::App& tool);

}  // namespace cartan::cli
