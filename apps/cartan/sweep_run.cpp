#include "sweep_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <system_error>
#include <thread>
#include <vector>

namespace cartan::cli {

std::string ProgressReport::line(std::size_t done, std::size_t total, std::size_t failed, double seconds) {
  constexpr std::size_t kWidth = 10;
  const std::size_t filled = total == 0 ? kWidth : done * kWidth / total;
  std::ostringstream out;
  out << '[' << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] " << done << '/' << total
      << " done, " << failed << " failed, " << std::fixed << std::setprecision(1) << seconds << " s";
  return out.str();
}

void ProgressReport::update(std::size_t done, std::size_t failed, double seconds) {
  if (finished_) return;
  finished_ = done == total_;
  if (terminal_) {
    std::cerr << '\r' << line(done, total_, failed, seconds) << (finished_ ? "\n" : "") << std::flush;
    return;
  }
  const std::size_t tenths = total_ == 0 ? 10 : done * 10 / total_;
  if (tenths > reported_tenths_ || finished_) {
    reported_tenths_ = tenths;
    std::cerr << line(done, total_, failed, seconds) << '\n' << std::flush;
  }
}

void run_in_parallel(std::size_t count, unsigned jobs, const std::function<bool(std::size_t)>& solve_point,
                     ProgressReport* report) {
  const auto start = std::chrono::steady_clock::now();
  std::atomic<std::size_t> next{0};
  std::size_t done = 0, failed = 0;  // guarded by mutex
  std::mutex mutex;
  std::condition_variable changed;
  const auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      const bool point_failed = solve_point(i);
      {
        std::lock_guard lock(mutex);  // the reporting thread sees done and failed change together
        failed += point_failed ? 1 : 0;
        ++done;
      }
      changed.notify_one();
    }
  };
  std::vector<std::thread> pool;
  const std::size_t threads = std::min<std::size_t>(std::max(jobs, 1u), std::max<std::size_t>(count, 1));
  for (std::size_t k = 0; k < threads; ++k) {
    try {
      pool.emplace_back(worker);
    } catch (const std::system_error&) {  // out of threads: run on those already started
      if (pool.empty()) throw;
      break;
    }
  }
  const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  {
    std::unique_lock lock(mutex);
    while (done < count) {
      changed.wait_for(lock, std::chrono::milliseconds(100));
      if (report == nullptr) continue;
      const std::size_t done_now = done, failed_now = failed;
      lock.unlock();  // workers keep going while the line is written
      report->update(done_now, failed_now, seconds());
      lock.lock();
    }
  }
  for (auto& t : pool) t.join();
  if (report != nullptr) report->update(done, failed, seconds());
}

}  // namespace cartan::cli
