#pragma once
// The default strategy's record of its attempts, compiled once (src/solvers/attempts.cpp): which
// method ran with which status, the best failed attempt of the requested problem (the smallest
// scaled residual), the work of all, and the words of the result (docs/design/one-core.md S7).
// The strategy itself (methods/lie_group/solve.hpp) decides what to try.

#include <functional>
#include <string>
#include <vector>

#include "cartan/solvers/continuation.hpp"

namespace cartan::solvers {

class Attempts {
 public:
  /// `empty`: a result without trajectory (the returned one when no attempt had any);
  /// `aux_scale`: the requested problem's auxiliary unit, asked for when a failed attempt is sized.
  Attempts(PathResultPtr empty, std::function<double()> aux_scale);

  /// Records the attempt `name` and its result: true when it solved the problem (it is then the
  /// result, its branch "<name> (<its branch>), after <failed ones> failed"). A failed attempt
  /// becomes the result if it is of the requested problem and its scaled residual is the smallest.
  bool attempt(const std::string& name, PathResultPtr result, bool requested_problem = true);
  /// The last failed attempt is not named among the failures of a later success.
  void forget_last_failure();
  /// Sweeps made outside the attempts (a start that fed the next attempt).
  void add_sweeps(int sweeps);
  /// The result: the success, or the best failed attempt with status StrategyFailed (Interrupted
  /// if `stopped`) and branch "failed: <every attempt>"; its counters the sum of all; its message
  /// "default strategy: <every attempt>; the returned result: <its message>".
  PathResultPtr finish(bool solved, bool stopped);

 private:
  PathResultPtr best_;
  std::function<double()> aux_scale_;
  double best_size_;
  std::vector<std::string> failed_;  ///< "continuation in T", ...
  std::string log_;                  ///< "shooting: no-progress; continuation in T: converged"
  int sweeps_ = 0, iterations_ = 0;
};

}  // namespace cartan::solvers
