#pragma once
// What a `cartan` command leaves behind: its output whole or nothing, also under Ctrl-C.
// While an InterruptScope lives, SIGINT only raises a flag (interrupted()); the solvers poll it
// through their monitor (cartan/monitor.hpp) and stop with status interrupted, and the commands
// check it before and after writing. An interrupted command leaves no output file (the one it
// was writing is removed), says "<command>: interrupted (no output written)" and exits 130.

#include <string>
#include <string_view>

#include "cartan/monitor.hpp"

namespace cartan::cli {

/// SIGINT raises the flag while this lives (main's whole run); the previous handler after.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

/// True once SIGINT arrived inside an InterruptScope.
bool interrupted();

/// `monitor` stopping also on SIGINT inside an InterruptScope, polled inside long sweeps too.
SolveMonitor interruptible(SolveMonitor monitor);

/// The exit of an interrupted command: "<command>: interrupted (no output written)" on stderr, 130.
int exit_interrupted(std::string_view command);

/// Throws std::invalid_argument "<what> = <path> cannot be written" unless `path` could be
/// written (an existing writable file, or a writable directory to create it in), without
/// creating or touching it: checked before hours of solving.
void require_writable(const std::string& path, const std::string& what);

/// Writes `text` to `path` (stdout when empty), whole or not at all: into a file beside it, then
/// renamed into place. Returns false when the command was interrupted (interrupted()) before the
/// output was complete, and then nothing is left at `path`. Throws std::invalid_argument
/// "<what> = <path> cannot be written" (nothing left either) when the file cannot be written.
bool write_output(const std::string& text, const std::string& path, const std::string& what);

}  // namespace cartan::cli
