// The default strategy's record of attempts (solvers/attempts.hpp) on scripted results, with no
// solver: words, the best failed attempt of the requested problem, summed work, stops.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "cartan/solvers/attempts.hpp"
#include "solvers/scripted_result.hpp"

namespace cartan::solvers {
namespace {

Attempts attempts_with_scale(double scale, int* asked = nullptr) {
  return Attempts(scripted(Status::NotConverged, 0, 0, 0, 0, "", false), [=] {
    if (asked != nullptr) ++*asked;
    return scale;
  });
}

TEST(Attempts, ASuccessNamesThePathAndTheFailuresBeforeIt) {
  Attempts a = attempts_with_scale(2);
  EXPECT_FALSE(a.attempt("shooting", scripted(Status::NoProgress, 0.5, 0, 10, 6, "lm")));
  EXPECT_FALSE(a.attempt("continuation in T", scripted(Status::ContinuationFailed, 0.1, 0, 20, 9, "path")));
  auto win = scripted(Status::Converged, 1e-12, 0, 30, 4, "won");
  win->core().branch = "continued in lambda from lambda = 0";
  EXPECT_TRUE(a.attempt("continuation in lambda from 0", std::move(win)));
  const PathResultPtr r = a.finish(true, false);
  EXPECT_EQ(r->core().status, Status::Converged);
  EXPECT_EQ(r->core().branch,
            "continuation in lambda from 0 (continued in lambda from lambda = 0), after shooting and continuation in T failed");
  EXPECT_EQ(r->core().message, "default strategy: shooting: no-progress; continuation in T: continuation-failed; "
                               "continuation in lambda from 0: converged; the returned result: won");
  EXPECT_EQ(r->core().sweeps, 60);  // every attempt's work
  EXPECT_EQ(r->core().inner_iterations, 19);
}

TEST(Attempts, AFailureReturnsTheSmallestScaledResidualOfTheRequestedProblem) {
  int asked = 0;
  Attempts a = attempts_with_scale(10, &asked);
  // hypot(error, xi / 10): 0.5 against hypot(0.3, 0.6) = 0.67; the third is another problem's
  // stage (requested_problem false) and the fourth has no trajectory: neither is sized.
  EXPECT_FALSE(a.attempt("shooting", scripted(Status::NoProgress, 0.3, 6, 1, 1, "first")));
  EXPECT_FALSE(a.attempt("continuation in T", scripted(Status::ContinuationFailed, 0.4, 3, 2, 2, "second")));
  EXPECT_FALSE(a.attempt("collocation", scripted(Status::NotConverged, 1e-3, 0, 4, 4, "third"), false));
  EXPECT_FALSE(a.attempt("multiple shooting", scripted(Status::MaxIterations, 0, 0, 8, 8, "fourth", false)));
  EXPECT_EQ(asked, 2);
  a.add_sweeps(16);
  const PathResultPtr r = a.finish(false, false);
  EXPECT_EQ(r->core().status, Status::StrategyFailed);
  EXPECT_EQ(r->core().terminal_error, 0.4);
  EXPECT_EQ(r->core().branch, "failed: shooting: no-progress; continuation in T: continuation-failed; collocation: "
                              "not-converged; multiple shooting: max-iterations");
  EXPECT_EQ(r->core().message.substr(r->core().message.size() - 6), "second");
  EXPECT_EQ(r->core().sweeps, 31);
  EXPECT_EQ(r->core().inner_iterations, 15);
}

TEST(Attempts, AStoppedStrategyIsInterruptedAndAForgottenFailureIsNotNamed) {
  Attempts stopped = attempts_with_scale(1);
  EXPECT_FALSE(stopped.attempt("shooting", scripted(Status::Interrupted, 0.2, 0, 3, 3, "stop")));
  EXPECT_EQ(stopped.finish(false, true)->core().status, Status::Interrupted);

  Attempts a = attempts_with_scale(1);
  EXPECT_FALSE(a.attempt("shooting", scripted(Status::NoProgress, 0.2, 0, 1, 1, "")));
  EXPECT_FALSE(a.attempt("shooting", scripted(Status::MaxIterations, 0.1, 0, 1, 1, "")));  // a polish that failed
  a.forget_last_failure();
  EXPECT_TRUE(a.attempt("collocation", scripted(Status::Converged, 0, 0, 1, 1, "")));
  EXPECT_EQ(a.finish(true, false)->core().branch, "collocation, after shooting failed");
}

}  // namespace
}  // namespace cartan::solvers
