#pragma once
// Progress reports and stop requests for long solves. Every iterative solver (Levenberg–Marquardt,
// collocation's Newton, continuation, the default strategy) calls `report` once per iteration and
// polls `stop_requested`: the CLI's SIGINT handler and Python's Ctrl-C (PyErr_CheckSignals) stop a
// solve through it, and the solver returns Status::Interrupted. A deadline (SolveOptions::time_limit)
// stops it the same way; the solve's entry point then reports Status::TimeLimit. The deadline and a
// cancel flag (the CLI's SIGINT flag, Python's cancel token) are also polled inside long sweeps
// (`stop_pending`: cheap, no callback), so that a solve stops within about a millisecond of work
// however long its iterations are; the stop callback runs once per iteration, and every
// kCallbackInterval inside the long steps of an iteration that poll() (a dense factorisation).

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace cartan {

/// One iteration of one stage of a solve: e.g. {"shooting", 4, 3.2e-7}.
struct Progress {
  std::string_view stage;
  int iteration = 0;
  double residual = 0;
};

/// The steps between a loop's polls, a power of two adapted to the loop's pace so that polls are
/// 0.25-1 ms apart: from 1, doubled while two polls are less than kPollsApart / 4 apart (up to
/// `most`), halved while they are more than kPollsApart apart (a step of Python callbacks takes
/// milliseconds, one of C++ arithmetic microseconds). The sweeps' (SolveMonitor::stop_pending_at)
/// and collocation's sweeps of f.
class PollPacer {
 public:
  using Clock = std::chrono::steady_clock;
  /// The time the polls aim to be apart at most.
  static constexpr std::chrono::microseconds kPollsApart{1000};

  explicit PollPacer(long most) : most_(most) {}
  /// Whether the loop polls at its step k (k + 1 a multiple of the interval).
  bool due(long k) const { return ((k + 1) & (interval_ - 1)) == 0; }
  /// At a poll: the time now, the interval adapted to the time since the previous poll (or since
  /// `since`, a loop's beginning, when that is later).
  Clock::time_point polled(Clock::time_point since = {}) {
    const Clock::time_point now = Clock::now();
    const auto apart = now - std::max(since, last_);
    last_ = now;
    if (apart > kPollsApart && interval_ > 1) {
      interval_ /= 2;
    } else if (apart < kPollsApart / 4 && interval_ < most_) {
      interval_ *= 2;
    }
    return now;
  }

 private:
  long most_;
  long interval_ = 1;
  Clock::time_point last_ = Clock::now();
};

class SolveMonitor {
 public:
  using ProgressCallback = std::function<void(const Progress&)>;
  using StopCallback = std::function<bool()>;

  SolveMonitor() = default;
  SolveMonitor(ProgressCallback progress, StopCallback stop) : progress_(std::move(progress)), stop_(std::move(stop)) {}

  /// True once a stop was requested (then it stays true: solvers may poll it several times).
  bool stop_requested() const {
    if (!stopped_ && (stop_pending() || (stop_ && stop_()))) stopped_ = true;
    return stopped_;
  }
  /// The cancel flag is raised or the deadline passed: never calls back, never throws, costs a
  /// clock read. Sweeps poll it every kStepsBetweenPolls steps and stop as a failed evaluation;
  /// the solver's next stop_requested() then ends the solve.
  bool stop_pending() const { return (cancel_ && cancel_->load(std::memory_order_relaxed)) || deadline_passed(); }
  /// The most steps a sweep runs between two polls (where steps take microseconds).
  static constexpr int kStepsBetweenPolls = 1024;
  /// What a sweep of `steps` steps, begun at `begin`, polls at its step k: stop_pending() every
  /// so many steps (a PollPacer's, at most kStepsBetweenPolls: every 1024 steps of Python callbacks
  /// was seconds), false between them and without a monitor. Its message, when true: stopped_message(k). Until the solver has timed a
  /// whole sweep (reserve_after_stop), a poll from step kStepsBetweenPolls on also projects the
  /// reserve from this sweep's pace:
  /// `after_stop` times the whole sweep's projected time (the work after a stop, in sweeps of this
  /// kind), so that a sweep longer than the time limit itself stops in time for what follows.
  static bool stop_pending_at(const SolveMonitor* monitor, int k, int steps,
                              std::chrono::steady_clock::time_point begin, double after_stop) {
    if (monitor == nullptr || !monitor->pacer_.due(k)) return false;
    const auto now = monitor->pacer_.polled(begin);
    // The pace is projected from kStepsBetweenPolls steps on (as before the interval adapted): the
    // first steps' pace (cold caches, first pages) projected a reserve of seconds, and a 0.5 s
    // limit stopped a solve at 0.12 s.
    if (monitor->deadline_ && !monitor->deadline_->timed.load(std::memory_order_relaxed) && k + 1 >= kStepsBetweenPolls) {
      const std::chrono::duration<double> pace = (now - begin) / double(k + 1);
      monitor->deadline_->reserve_ns.store(
          std::chrono::duration_cast<std::chrono::nanoseconds>(pace * (after_stop * steps)).count(),
          std::memory_order_relaxed);
    }
    return monitor->stop_pending();
  }
  static std::string stopped_message(int k) {
    return "stopped at step " + std::to_string(k) + " (time limit or cancellation)";
  }
  /// stop_pending(), and the stop callback as stop_requested() does, but at most every
  /// kCallbackInterval (Python's callback takes the GIL): for work inside an iteration that is not
  /// a sweep and may last seconds (a dense Hessian and its LU, a collocation Jacobian), polled
  /// between pieces of a few milliseconds. Once true, stays true, and stop_requested() is true too.
  bool poll() const {
    if (stopped_ || stop_pending()) return stopped_ = true;
    if (!stop_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (now < next_callback_) return false;
    next_callback_ = now + kCallbackInterval;
    return stop_requested();
  }
  /// poll() of `monitor`, false without one.
  static bool poll(const SolveMonitor* monitor) { return monitor != nullptr && monitor->poll(); }
  static constexpr std::chrono::milliseconds kCallbackInterval{20};
  /// A copy reporting under `name`, or nothing without a monitor (for an options' monitor pointer).
  static std::optional<SolveMonitor> staged(const SolveMonitor* monitor, std::string name) {
    return monitor == nullptr ? std::nullopt : std::optional<SolveMonitor>(monitor->stage(std::move(name)));
  }
  /// The same callbacks, stopping also once `flag` is raised (from any thread or a signal handler).
  SolveMonitor with_cancel_flag(std::shared_ptr<const std::atomic<bool>> flag) const {
    SolveMonitor copy = *this;
    copy.cancel_ = std::move(flag);
    return copy;
  }
  /// The same callbacks, stopping also from `deadline` on (shared by every copy, stages included);
  /// an earlier deadline this monitor has stays (a solve inside a timed one keeps its caller's).
  SolveMonitor with_deadline(std::chrono::steady_clock::time_point deadline) const {
    if (deadline_ && deadline_->at <= deadline) return *this;  // a nested solve keeps its caller's
    SolveMonitor copy = *this;
    copy.deadline_ = std::make_shared<Deadline>();
    copy.deadline_->at = deadline;
    return copy;
  }
  /// True from the deadline less the reserve on; once true, stays true (`expired`).
  bool deadline_passed() const { return deadline_passed_after(std::chrono::nanoseconds(0)); }
  /// stop_requested(), or the deadline would pass during `next` (the length of the iteration about to
  /// start, e.g. the last one's): an iteration that cannot end in time is not begun, and the
  /// deadline counts as passed from then on.
  bool stop_requested_before(std::chrono::nanoseconds next) const {
    if (!stopped_ && deadline_passed_after(next)) stopped_ = true;
    return stop_requested();
  }
  /// The work after a stop, in sweeps of the kind that polls (stop_pending_at's `after_stop`, and
  /// the factor on a timed sweep for reserve_after_stop): `finishing` where the sweep records its
  /// nodes, else a recording sweep into fresh storage, about 2 plain sweeps (its pages are new;
  /// bench/README.md, "Interruption"; a stopped result has no action); a tangent-linear sweep costs
  /// about 3 plain ones.
  static constexpr double sweeps_after_stop(bool records, bool tangent_linear, double finishing = 0.0) {
    return (records ? finishing : 2.0) / (tangent_linear ? 3 : 1);
  }
  /// The time a solver needs after a stop to return its result (a recording sweep, the action):
  /// the deadline then applies that much earlier, so that the call ends near its time limit
  /// rather than that much after it. Solvers update it as they measure their sweeps.
  void reserve_after_stop(std::chrono::nanoseconds finishing) const {
    if (!deadline_) return;
    deadline_->reserve_ns.store(finishing.count(), std::memory_order_relaxed);
    deadline_->timed.store(true, std::memory_order_relaxed);
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
  struct Deadline {
    std::chrono::steady_clock::time_point at;
    std::atomic<long long> reserve_ns{0};
    std::atomic<bool> timed{false};  ///< a solver has set the reserve from a whole sweep
    std::atomic<bool> expired{false};
  };
  bool deadline_passed_after(std::chrono::nanoseconds next) const {
    if (!deadline_) return false;
    if (deadline_->expired.load(std::memory_order_relaxed)) return true;
    const std::chrono::nanoseconds reserve(deadline_->reserve_ns.load(std::memory_order_relaxed));
    if (std::chrono::steady_clock::now() + next + reserve < deadline_->at) return false;
    deadline_->expired.store(true, std::memory_order_relaxed);
    return true;
  }
  std::shared_ptr<Deadline> deadline_;
  std::shared_ptr<const std::atomic<bool>> cancel_;
  mutable bool stopped_ = false;
  mutable PollPacer pacer_{kStepsBetweenPolls};  ///< stop_pending_at's steps between polls
  mutable std::chrono::steady_clock::time_point next_callback_{};  ///< poll()'s next call of stop_
};

}  // namespace cartan
