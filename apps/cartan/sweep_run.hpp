#pragma once
// Running the points of a sweep on a pool of threads, with a progress report on stderr from the
// calling thread only (so it never interleaves with itself or with the results on stdout).

#include <cstddef>
#include <functional>
#include <string>

namespace cartan::cli {

/// The progress line "[#####.....] 12/40 done, 1 failed, 3.2 s": redrawn in place with '\r' when
/// stderr is a terminal, otherwise one line each time another tenth of the points is done.
class ProgressReport {
 public:
  ProgressReport(std::size_t total, bool terminal) : total_(total), terminal_(terminal) {}
  /// Called by the thread that started the pool, after every change and periodically.
  void update(std::size_t done, std::size_t failed, double seconds);

  /// The line itself (no '\r', no newline).
  static std::string line(std::size_t done, std::size_t total, std::size_t failed, double seconds);

 private:
  std::size_t total_;
  bool terminal_;
  std::size_t reported_tenths_ = 0;  ///< not a terminal: tenths of the points already reported
  bool finished_ = false;
};

/// Calls solve_point(i) for every i in [0, count) on min(jobs, count) threads that take indices
/// from one atomic counter; solve_point must not throw and returns whether point i failed. With a
/// report, the calling thread updates it about 10 times a second and once at the end.
void run_in_parallel(std::size_t count, unsigned jobs, const std::function<bool(std::size_t)>& solve_point,
                     ProgressReport* report);

}  // namespace cartan::cli
