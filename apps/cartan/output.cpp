#include "output.hpp"

#include "command.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <memory>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace cartan::cli {

namespace {

// Lock-free, hence safe to set from the signal handler; shared with the solvers' monitors.
const std::shared_ptr<std::atomic<bool>> interrupt_flag = std::make_shared<std::atomic<bool>>(false);
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool>* const raw_flag = interrupt_flag.get();

extern "C" void on_sigint(int) { raw_flag->store(true); }

using Handler = void (*)(int);
Handler previous_handler = SIG_DFL;

}  // namespace

InterruptScope::InterruptScope() { previous_handler = std::signal(SIGINT, on_sigint); }

InterruptScope::~InterruptScope() { std::signal(SIGINT, previous_handler == SIG_ERR ? SIG_DFL : previous_handler); }

bool interrupted() { return raw_flag->load(); }

SolveMonitor interruptible(SolveMonitor monitor) { return monitor.with_cancel_flag(interrupt_flag); }

int exit_interrupted(std::string_view command) {
  std::cerr << command << ": interrupted (no output written)\n";
  return kExitInterrupted;
}

void require_writable(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path target(path);
  const bool exists = fs::exists(target, error);
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const bool ok = exists ? !fs::is_directory(target, error) && ::access(path.c_str(), W_OK) == 0
                         : fs::is_directory(directory, error) && ::access(directory.c_str(), W_OK) == 0;
  if (!ok) throw std::invalid_argument(what + " = " + path + " cannot be written");
}

bool write_output(const std::string& text, const std::string& path, const std::string& what) {
  if (interrupted()) return false;
  if (path.empty()) {
    std::cout << text << std::flush;
    return !interrupted();
  }
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial);
    if (!out) throw std::invalid_argument(what + " = " + path + " cannot be written");
    out << text;
    out.close();
    if (!out) {
      std::remove(partial.c_str());
      throw std::invalid_argument(what + " = " + path + " could not be written completely");
    }
  }
  if (interrupted()) {
    std::remove(partial.c_str());
    return false;
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    std::remove(partial.c_str());
    throw std::invalid_argument(what + " = " + path + " cannot be written");
  }
  if (interrupted()) {  // SIGINT during the rename: the command still reports it, and leaves nothing
    std::remove(path.c_str());
    return false;
  }
  return true;
}

}  // namespace cartan::cli
