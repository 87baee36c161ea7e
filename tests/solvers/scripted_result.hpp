#pragma once
// A PathResult with scripted figures, for the tests of the compiled strategy pieces (no solver).
#include <memory>
#include <string>
#include <utility>

#include "cartan/solvers/continuation.hpp"

namespace cartan::solvers {

struct Scripted final : PathResult {
  ResultCore value;
  bool trajectory = true;
  ResultCore& core() override { return value; }
  const ResultCore& core() const override { return value; }
  Eigen::VectorXd velocity() const override { return Eigen::VectorXd::Zero(1); }
  Eigen::VectorXd auxiliary() const override { return Eigen::VectorXd::Zero(1); }
  bool has_trajectory() const override { return trajectory; }
  PathResultPtr clone() const override { return std::make_unique<Scripted>(*this); }
};

/// A result with `status`, terminal figures (error, xi) and work (sweeps, iterations).
inline PathResultPtr scripted(Status status, double error, double xi, int sweeps, int iterations, std::string message,
                              bool trajectory = true) {
  auto r = std::make_unique<Scripted>();
  r->value.status = status;
  r->value.terminal_error = error;
  r->value.xi_terminal = xi;
  r->value.sweeps = sweeps;
  r->value.inner_iterations = iterations;
  r->value.message = std::move(message);
  r->trajectory = trajectory;
  return r;
}

}  // namespace cartan::solvers
