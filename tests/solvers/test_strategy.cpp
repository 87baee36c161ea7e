// The default strategy (solvers/strategy.hpp) on a scripted kernel, with no solver: the order of
// the attempts and what gates each (capabilities, N, time rescaling, lambda), the reuse of the
// failed first shooting, the polish of collocation, the words, the work, stops.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cartan/solvers/strategy.hpp"
#include "solvers/scripted_result.hpp"

namespace cartan::solvers {
namespace {

/// Every method returns the status scripted for it (NoProgress when none is) with the residual
/// `error` and one sweep, and logs its call.
class ScriptedKernel final : public StrategyKernel {
 public:
  std::map<std::string, Status> outcome;
  std::map<std::string, double> error;
  std::vector<std::string> calls;
  int N = 100;
  bool rescaling_invariant = false;
  std::optional<double> lambda_;
  bool collocation = false, multiple = false, guess = false;
  int window = 7;
  int window_seen = -1;
  std::string failed_direct_seen;  ///< the message of the failed shooting continuation in T got
  std::function<void()> after_call;

  PathResultPtr empty() const override { return scripted(Status::NotConverged, 0, 0, 0, 0, "empty", false); }
  double auxiliary_scale() const override { return 1; }
  bool guessed() const override { return guess; }
  int steps() const override { return N; }
  bool time_rescaling_invariant() const override { return rescaling_invariant; }
  std::optional<double> lambda() const override { return lambda_; }
  bool has_collocation() const override { return collocation; }
  bool has_multiple_shooting() const override { return multiple; }
  int first_shooting_window() const override { return window; }

  PathResultPtr shoot(const ShootingOptions& options) override {
    window_seen = options.no_progress_window;
    return run("shooting");
  }
  PathResultPtr shoot_from(const ShootingOptions&, const PathResult& start) override {
    EXPECT_EQ(start.core().message, "collocation");
    return run("polish");
  }
  PathResultPtr continue_in_T(const ContinuationOptions&, PathResultPtr failed_direct) override {
    failed_direct_seen = failed_direct ? failed_direct->core().message : "none";
    return run("T");
  }
  PathResultPtr continue_in_lambda(const ContinuationOptions&, double start) override {
    return run("lambda " + std::to_string(static_cast<int>(start)));
  }
  PathResultPtr collocate(const SolveOptions& options, int samples) override {
    EXPECT_EQ(options.method, Method::Collocation);
    EXPECT_EQ(samples, N + 1);  // the result on the scheme's nodes
    return run("collocation");
  }
  PathResultPtr multiple_shoot(const SolveOptions&, const SolveMonitor& stage) override {
    EXPECT_EQ(stage.stage_name(), "multiple shooting");
    return run("multiple");
  }

 private:
  PathResultPtr run(const std::string& name) {
    calls.push_back(name);
    const Status status = outcome.contains(name) ? outcome.at(name) : Status::NoProgress;
    const double e = error.contains(name) ? error.at(name) : 1.0;
    PathResultPtr r = scripted(status, status == Status::Converged ? 0.0 : e, 0, 1, 2, name);
    if (after_call) after_call();
    return r;
  }
};

using Calls = std::vector<std::string>;

TEST(Strategy, TriesEveryCapabilityInOrderAndReturnsTheBestFailure) {
  ScriptedKernel k;
  k.lambda_ = 0.5;
  k.collocation = k.multiple = true;
  k.error = {{"shooting", 0.3}, {"T", 0.2}, {"lambda 0", 0.9}, {"lambda 1", 0.4}, {"collocation", 0.25}, {"multiple", 0.6}};
  k.outcome["collocation"] = Status::NotConverged;
  const PathResultPtr r = default_strategy(k, SolveOptions{});
  EXPECT_EQ(k.calls, (Calls{"shooting", "T", "lambda 0", "lambda 1", "collocation", "multiple"}));
  EXPECT_EQ(k.window_seen, 7);               // the kernel's window for the first shooting
  EXPECT_EQ(k.failed_direct_seen, "shooting");  // continuation in T starts from the failed shooting
  EXPECT_EQ(r->core().status, Status::StrategyFailed);
  EXPECT_EQ(r->core().terminal_error, 0.2);  // the smallest residual of the requested problem
  EXPECT_EQ(r->core().branch, "failed: shooting: no-progress; continuation in T: no-progress; continuation in lambda "
                              "from 0: no-progress; continuation in lambda from 1: no-progress; collocation: "
                              "not-converged; multiple shooting: no-progress");
  EXPECT_EQ(r->core().sweeps, 6);  // every attempt's work
  EXPECT_EQ(r->core().inner_iterations, 12);
}

TEST(Strategy, WithoutCapabilitiesOnlyShootingAndContinuationInTRun) {
  ScriptedKernel k;
  default_strategy(k, SolveOptions{});
  EXPECT_EQ(k.calls, (Calls{"shooting", "T"}));
}

TEST(Strategy, NoContinuationInTWhereAShorterHorizonIsTheSameProblemOrNCannotBeHalved) {
  ScriptedKernel invariant;
  invariant.rescaling_invariant = true;
  default_strategy(invariant, SolveOptions{});
  EXPECT_EQ(invariant.calls, (Calls{"shooting"}));
  ScriptedKernel short_grid;
  short_grid.N = 15;  // < 16 steps
  short_grid.multiple = true;
  default_strategy(short_grid, SolveOptions{});
  EXPECT_EQ(short_grid.calls, (Calls{"shooting", "multiple"}));
  ScriptedKernel one_step;
  one_step.N = 1;  // multiple shooting needs two steps
  one_step.multiple = true;
  default_strategy(one_step, SolveOptions{});
  EXPECT_EQ(one_step.calls, (Calls{"shooting"}));
}

TEST(Strategy, ContinuationInLambdaSkipsTheFlatConnectionThatIsTheProblem) {
  ScriptedKernel k;
  k.lambda_ = 1.0;
  k.outcome["lambda 0"] = Status::Converged;
  const PathResultPtr r = default_strategy(k, SolveOptions{});
  EXPECT_EQ(k.calls, (Calls{"shooting", "T", "lambda 0"}));
  EXPECT_EQ(r->core().status, Status::Converged);
  EXPECT_EQ(r->core().branch, "continuation in lambda from 0, after shooting and continuation in T failed");
  ScriptedKernel at_zero;
  at_zero.lambda_ = 0.0;
  default_strategy(at_zero, SolveOptions{});
  EXPECT_EQ(at_zero.calls, (Calls{"shooting", "T", "lambda 1"}));
}

TEST(Strategy, CollocationIsPolishedByShootingAndKeptWhenThePolishFails) {
  ScriptedKernel polished;
  polished.collocation = true;
  polished.guess = true;
  polished.outcome = {{"collocation", Status::Converged}, {"polish", Status::Converged}};
  const PathResultPtr p = default_strategy(polished, SolveOptions{});
  EXPECT_EQ(polished.calls, (Calls{"shooting", "T", "collocation", "polish"}));
  EXPECT_EQ(p->core().message.substr(p->core().message.size() - 6), "polish");
  EXPECT_EQ(p->core().branch, "shooting (from the collocation solution), after shooting and continuation in T failed");
  EXPECT_EQ(p->core().sweeps, 4);  // the collocation's work counts

  ScriptedKernel kept;
  kept.collocation = true;
  kept.outcome = {{"collocation", Status::Converged}, {"polish", Status::MaxIterations}};
  const PathResultPtr c = default_strategy(kept, SolveOptions{});
  EXPECT_EQ(c->core().status, Status::Converged);
  EXPECT_EQ(c->core().branch,
            "collocation (of the continuous problem; shooting the discrete scheme from it failed), after shooting and "
            "continuation in T failed");
}

TEST(Strategy, TheFirstShootingNamesItsGuessAndASuccessEndsTheStrategy) {
  ScriptedKernel k;
  k.guess = true;
  k.outcome["shooting"] = Status::Converged;
  const PathResultPtr r = default_strategy(k, SolveOptions{});
  EXPECT_EQ(k.calls, (Calls{"shooting"}));
  EXPECT_EQ(r->core().branch, "shooting (direct from the given guess)");
  EXPECT_EQ(r->core().message, "default strategy: shooting: converged; the returned result: shooting");
}

TEST(Strategy, AStopEndsTheStrategyInterrupted) {
  ScriptedKernel k;
  k.collocation = k.multiple = true;
  k.lambda_ = 0.5;
  bool stop = false;
  k.after_call = [&] { stop = true; };  // the stop arrives during the first shooting
  SolveOptions options;
  options.monitor = SolveMonitor(nullptr, [&] { return stop; });
  const PathResultPtr r = default_strategy(k, options);
  EXPECT_EQ(k.calls, (Calls{"shooting"}));
  EXPECT_EQ(k.failed_direct_seen, "");  // continuation in T never ran
  EXPECT_EQ(r->core().status, Status::Interrupted);
}


// The explicit methods (run_method): each goes to the kernel's method, shooting with the options'
// window (0: no abandon), continuation in T with no failed attempt (the path makes its own first
// stage, D7), continuation in lambda from lambda_start, collocation at the options' samples;
// a method the kernel lacks is a logic error (each solve's validate refuses it first, by name).
TEST(Strategy, AnExplicitMethodRunsTheKernelsMethodAlone) {
  const auto run = [](Method method, Continuation continuation, ScriptedKernel& k) {
    SolveOptions options;
    options.method = method;
    options.continuation = continuation;
    options.samples = k.N + 1;
    if (continuation == Continuation::Lambda) options.lambda_start = 1.0;
    return run_method(k, options);
  };
  ScriptedKernel k;
  k.collocation = k.multiple = true;
  PathResultPtr r = run(Method::Shooting, Continuation::None, k);
  EXPECT_EQ(k.calls, (Calls{"shooting"}));
  EXPECT_EQ(k.window_seen, 0);
  EXPECT_EQ(r->core().branch, "direct from the geodesic guess");
  EXPECT_EQ(r->core().status, Status::NoProgress);  // the kernel's result as it is
  k.calls.clear();
  run(Method::Shooting, Continuation::T, k);
  EXPECT_EQ(k.calls, (Calls{"T"}));
  EXPECT_EQ(k.failed_direct_seen, "none");
  k.calls.clear();
  run(Method::Shooting, Continuation::Lambda, k);
  EXPECT_EQ(k.calls, (Calls{"lambda 1"}));
  k.calls.clear();
  run(Method::Collocation, Continuation::None, k);
  run(Method::MultipleShooting, Continuation::None, k);
  EXPECT_EQ(k.calls, (Calls{"collocation", "multiple"}));
  EXPECT_THROW(run(Method::TwoLevel, Continuation::None, k), std::logic_error);
  EXPECT_THROW(run(Method::Variational, Continuation::None, k), std::logic_error);
  k.calls.clear();
  k.outcome["shooting"] = Status::Converged;
  EXPECT_EQ(run(Method::Auto, Continuation::None, k)->core().branch, "shooting (direct from the geodesic guess)");
}

}  // namespace
}  // namespace cartan::solvers
