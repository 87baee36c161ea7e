// The variational method's compiled Newton iteration (solvers/variational.hpp) on toy gradient
// systems with no group: x in R^2 with gradient (x0^3 - 1, x1 - 2) (the root (1, 2), where
// Newton converges quadratically), a singular Hessian, a non-finite start, no unknowns.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cartan/solvers/variational.hpp"

namespace cartan::solvers {
namespace {

struct ToyPath final : PathSystem {
  Eigen::Vector2d x{3, 0}, trial_x;
  bool singular = false;
  Eigen::Index size = 2;
  int trials = 0;

  static Eigen::VectorXd gradient_at(const Eigen::Vector2d& y) { return Eigen::Vector2d(y[0] * y[0] * y[0] - 1, y[1] - 2); }
  Eigen::Index unknowns() const override { return size; }
  bool gradient(Eigen::VectorXd& out) override {
    out = gradient_at(x);
    return out.allFinite();
  }
  bool hessian(const Eigen::VectorXd&, Eigen::MatrixXd& out) override {
    out = Eigen::Vector2d(singular ? 0.0 : 3 * x[0] * x[0], 1).asDiagonal();
    return true;
  }
  bool trial(const Eigen::VectorXd& delta, double s, Eigen::VectorXd& out) override {
    ++trials;
    trial_x = x + s * delta;
    out = gradient_at(trial_x);
    return out.allFinite();
  }
  void accept() override { x = trial_x; }
};

TEST(PathNewton, ConvergesToTheRootWithShrinkingCorrections) {
  ToyPath toy;
  std::vector<double> history;
  const PathNewtonOutcome out = newton_on_path(toy, {.tolerance = 1e-12}, history);
  EXPECT_EQ(out.status, Status::Converged) << out.why;
  EXPECT_NEAR(toy.x[0], 1, 1e-12);
  EXPECT_NEAR(toy.x[1], 2, 1e-12);
  ASSERT_EQ(static_cast<int>(history.size()), out.iterations);
  EXPECT_LE(history.back(), 1e-12);
  for (std::size_t k = 1; k < history.size(); ++k) EXPECT_LT(history[k], history[k - 1]);  // monotone (the test)
}

TEST(PathNewton, ASingularHessianANonFiniteStartAndTheIterationLimitAreStatuses) {
  ToyPath singular;
  singular.singular = true;
  std::vector<double> history;
  const PathNewtonOutcome s = newton_on_path(singular, {}, history);
  EXPECT_EQ(s.status, Status::SingularJacobian);
  EXPECT_EQ(s.why, "the Hessian is singular at iteration 0");

  ToyPath broken;
  broken.x = {std::numeric_limits<double>::infinity(), 0};
  EXPECT_EQ(newton_on_path(broken, {}, history).status, Status::NonFinite);

  ToyPath short_budget;
  const PathNewtonOutcome m = newton_on_path(short_budget, {.tolerance = 1e-12, .max_iterations = 2}, history);
  EXPECT_EQ(m.status, Status::MaxIterations);
  EXPECT_EQ(m.iterations, 2);

  ToyPath none;
  none.size = 0;  // N = 1: nothing to solve
  const PathNewtonOutcome n = newton_on_path(none, {}, history);
  EXPECT_EQ(n.status, Status::Converged);
  EXPECT_EQ(n.iterations, 0);
  EXPECT_EQ(none.trials, 0);
}

TEST(PathNewton, AStopRequestInterrupts) {
  ToyPath toy;
  std::vector<double> history;
  const SolveMonitor monitor(nullptr, [] { return true; });
  EXPECT_EQ(newton_on_path(toy, {.monitor = &monitor}, history).status, Status::Interrupted);
}

}  // namespace
}  // namespace cartan::solvers
