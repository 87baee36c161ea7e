#pragma once
// Progress reports and stop requests for long solves. Every iterative solver (Levenberg–Marquardt,
// collocation's Newton, continuation, the default strategy) calls `report` once per iteration and
// polls `stop_requested`: the CLI's SIGINT handler and Python's Ctrl-C (PyErr_CheckSignals) stop a
// solve through it, and the solver returns Status::Interrupted.

#include <functional>
#include <string>
#include <string_view>

namespace cartan {

/// One iteration of one stage of a solve: e.g. {"shooting", 4, 3.2e-7}.
struct Progress {
  std::string_view stage;
  int iteration = 0;
  double residual = 0;
};

class SolveMonitor {
 public:
  using ProgressCallback = std::function<void(const Progress&)>;
  using StopCallback = std::function<bool()>;

  SolveMonitor() = default;
  SolveMonitor(ProgressCallback progress, StopCallback stop) : progress_(std::move(progress)), stop_(std::move(stop)) {}

  /// True once a stop was requested (then it stays true: solvers may poll it several times).
  bool stop_requested() const {
    if (!stopped_ && stop_ && stop_()) stopped_ = true;
    return stopped_;
  }
  void report(int iteration, double residual) const {
    if (progress_) progress_({stage_, iteration, residual});
  }
  /// The same callbacks, reporting under another stage name.
  SolveMonitor stage(std::string name) const {
    SolveMonitor copy = *this;
    copy.stage_ = std::move(name);
    return copy;
  }
  const std::string& stage_name() const { return stage_; }

 private:
  ProgressCallback progress_;
  StopCallback stop_;
  std::string stage_;
  mutable bool stopped_ = false;
};

}  // namespace cartan
