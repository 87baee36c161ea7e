// The default strategy's record of attempts (solvers/attempts.hpp).
#include "cartan/solvers/attempts.hpp"

#include <limits>
#include <utility>

#include "cartan/enum_names.hpp"

namespace cartan::solvers {

Attempts::Attempts(PathResultPtr empty, std::function<double()> aux_scale)
    : best_(std::move(empty)), aux_scale_(std::move(aux_scale)), best_size_(std::numeric_limits<double>::infinity()) {}

bool Attempts::attempt(const std::string& name, PathResultPtr result, bool requested_problem) {
  ResultCore& core = result->core();
  sweeps_ += core.sweeps;
  iterations_ += core.inner_iterations;
  log_ += (log_.empty() ? "" : "; ") + name + ": " + std::string(to_string(core.status));
  if (core.converged()) {
    std::string after;
    for (std::size_t i = 0; i < failed_.size(); ++i) {
      after += (i ? (i + 1 == failed_.size() ? " and " : ", ") : "") + failed_[i];
    }
    core.branch = name + (core.branch.empty() ? "" : " (" + core.branch + ")") +
                  (failed_.empty() ? "" : ", after " + after + " failed");
    best_ = std::move(result);
    return true;
  }
  failed_.push_back(name);
  const double size = requested_problem && result->has_trajectory() ? scaled_residual(core, aux_scale_())
                                                                     : std::numeric_limits<double>::infinity();
  if (size < best_size_) {
    best_size_ = size;
    best_ = std::move(result);
  }
  return false;
}

void Attempts::forget_last_failure() {
  if (!failed_.empty()) failed_.pop_back();
}

void Attempts::add_sweeps(int sweeps) { sweeps_ += sweeps; }

PathResultPtr Attempts::finish(bool solved, bool stopped) {
  ResultCore& core = best_->core();
  core.sweeps = sweeps_;
  core.inner_iterations = iterations_;
  if (!solved) {
    core.status = stopped ? Status::Interrupted : Status::StrategyFailed;
    core.branch = "failed: " + log_;
  }
  core.message = "default strategy: " + log_ +
                 (core.message.empty() ? "; no attempt produced a trajectory to return"
                                       : "; the returned result: " + core.message);
  return std::move(best_);  // not a copy of its trajectory (0.3 GB at N = 2e6)
}

}  // namespace cartan::solvers
