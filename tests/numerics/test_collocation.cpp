// The collocation BVP solver (numerics/collocation.hpp) against closed forms, its measured order,
// standard test problems of SciPy's solve_bvp suite (written from their published equations),
// every failure status, and bad input.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cartan/monitor.hpp"
#include "cartan/numerics/collocation.hpp"
#include "cartan/numerics/scipy_refinement.hpp"
#include "cartan/solvers/collocation.hpp"
#include "solvers/scripted_result.hpp"

namespace cartan::numerics {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

/// y'' = 3/2 y^2, y(0) = 4, y(1) = 1: y = 4 / (1 + t)^2 (Ascher, Mattheij & Russell, one of
/// two solutions; the other has y'(0) ~ -36).
BvpSystem quadratic_problem(bool analytic_jacobian) {
  BvpSystem s;
  s.n = 2;
  s.rhs = [](double, ConstVectorRef y, ConstVectorRef, VectorRef dy) { dy << y[1], 1.5 * y[0] * y[0]; };
  s.bc = [](ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef, VectorRef r) { r << ya[0] - 4, yb[0] - 1; };
  if (analytic_jacobian) {
    s.rhs_jacobian = [](double, ConstVectorRef y, ConstVectorRef, MatrixRef dfdy, MatrixRef) {
      dfdy << 0, 1, 3 * y[0], 0;
    };
    s.bc_jacobian = [](ConstVectorRef, ConstVectorRef, ConstVectorRef, MatrixRef dya, MatrixRef dyb, MatrixRef) {
      dya << 1, 0, 0, 0;
      dyb << 0, 0, 1, 0;
    };
  }
  return s;
}

VectorXd quadratic_exact(double t) { return VectorXd{{4 / ((1 + t) * (1 + t)), -8 / std::pow(1 + t, 3)}}; }

VectorXd uniform(double a, double b, int nodes) { return VectorXd::LinSpaced(nodes, a, b); }

/// Values of `exact` at the mesh, perturbed by a smooth bump that vanishes at neither end.
template <class Exact>
MatrixXd perturbed_guess(const VectorXd& t, const Exact& exact, double size) {
  MatrixXd y(exact(t[0]).size(), t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) y.col(i) = exact(t[i]).array() + size * std::cos(t[i]);
  return y;
}

template <class Exact>
double max_error_at(const BvpResult& r, const VectorXd& times, const Exact& exact) {
  double worst = 0;
  for (double t : times) worst = std::max(worst, (r(t) - exact(t)).cwiseAbs().maxCoeff());
  return worst;
}

// Fourth order, measured: on fixed uniform meshes with h halving, the nodal error and the
// dense-output error must fall by 2^4. The three-stage Lobatto IIIA method has nodal order
// 2s - 2 = 4 and its C^1 cubic interpolant is O(h^4) uniformly; 0.3 allows the pre-asymptotic
// h^5 term at h = 1/8. Newton runs to tol = 1e-13 so its error stays far below the 1e-10 errors.
TEST(Collocation, MeasuredOrderIsFourOnFixedMeshes) {
  const BvpSystem s = quadratic_problem(false);
  const VectorXd dense = uniform(0, 1, 201);
  std::vector<double> nodal, interpolated;
  for (int intervals : {16, 32, 64, 128}) {
    const VectorXd t = uniform(0, 1, intervals + 1);
    const BvpResult r = solve_collocation_on_mesh(s, t, perturbed_guess(t, quadratic_exact, 0.3), VectorXd(0),
                                                  {.tol = 1e-13});
    ASSERT_TRUE(r.success()) << r.message;
    nodal.push_back(max_error_at(r, t, quadratic_exact));
    interpolated.push_back(max_error_at(r, dense, quadratic_exact));
  }
  for (std::size_t j = 0; j + 1 < nodal.size(); ++j) {
    EXPECT_NEAR(std::log2(nodal[j] / nodal[j + 1]), 4.0, 0.3) << nodal[j] << " " << nodal[j + 1];
    EXPECT_NEAR(std::log2(interpolated[j] / interpolated[j + 1]), 4.0, 0.3)
        << interpolated[j] << " " << interpolated[j + 1];
  }
}

// The residual control bounds what it claims: an independent dense sampling of the relative
// defect (S' - f(t, S)) / (1 + |f|) (21 points per interval, trapezoidal RMS) agrees with the
// reported per-interval RMS to 10% (both approximate the same integral of a smooth O(h^3)
// function), and every interval is below tol. The analytic and finite-difference Jacobians
// reach the same solution (same equations; only Newton's path differs, so to ~Newton's error).
TEST(Collocation, ResidualControlAndJacobians) {
  const VectorXd t = uniform(0, 1, 5);
  const MatrixXd guess = perturbed_guess(t, quadratic_exact, 0.3);
  const CollocationOptions options{.tol = 1e-6};
  const BvpResult fd = solve_collocation(quadratic_problem(false), t, guess, VectorXd(0), options);
  const BvpResult an = solve_collocation(quadratic_problem(true), t, guess, VectorXd(0), options);
  ASSERT_TRUE(fd.success()) << fd.message;
  ASSERT_TRUE(an.success()) << an.message;
  EXPECT_LE(fd.max_rms_residual, options.tol);
  EXPECT_EQ(fd.t.size(), an.t.size());
  EXPECT_LE((fd.y - an.y).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(an.rhs_evaluations, fd.rhs_evaluations);

  const BvpSystem s = quadratic_problem(false);
  const CubicHermite S = fd.interpolant();
  VectorXd f(2);
  for (Eigen::Index i = 0; i + 1 < fd.t.size(); ++i) {
    double sum = 0;
    constexpr int kPoints = 20;
    for (int j = 0; j <= kPoints; ++j) {
      const double tt = fd.t[i] + (fd.t[i + 1] - fd.t[i]) * j / kPoints;
      s.rhs(tt, S.value(tt), VectorXd(0), f);
      const double rho2 = ((S.derivative(tt) - f).array() / (1 + f.array().abs())).matrix().squaredNorm();
      sum += (j == 0 || j == kPoints ? 0.5 : 1.0) * rho2;
    }
    const double sampled = std::sqrt(sum / kPoints);
    EXPECT_NEAR(sampled, fd.rms_residual[i], 0.1 * fd.rms_residual[i]) << "interval " << i;
  }
  // The global error follows the residual: this problem is well conditioned (O(1) Green's
  // function), so an error within 10 tol is what the residual control promises.
  EXPECT_LE(max_error_at(fd, uniform(0, 1, 101), quadratic_exact), 10 * options.tol);
}

// SciPy's Sturm–Liouville test: y'' + k^2 y = 0, y(0) = y(1) = 0, y'(0) = k, k unknown.
// From k = 2.5 and a one-hump guess Newton finds the first eigenvalue k = pi, y = sin(pi t).
TEST(Collocation, EigenvalueProblemWithUnknownParameter) {
  BvpSystem s;
  s.n = 2;
  s.k = 1;
  s.rhs = [](double, ConstVectorRef y, ConstVectorRef p, VectorRef dy) { dy << y[1], -p[0] * p[0] * y[0]; };
  s.bc = [](ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef p, VectorRef r) { r << ya[0], yb[0], ya[1] - p[0]; };
  const VectorXd t = uniform(0, 1, 6);
  MatrixXd guess(2, t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) guess.col(i) << 4 * t[i] * (1 - t[i]), 4 - 8 * t[i];
  const double tol = 1e-7;
  const BvpResult r = solve_collocation(s, t, guess, VectorXd{{2.5}}, {.tol = tol});
  ASSERT_TRUE(r.success()) << r.message;
  // k and y are determined by a well-conditioned system: errors within 10 tol (as above).
  EXPECT_NEAR(r.p[0], M_PI, 10 * tol);
  const auto exact = [](double x) { return VectorXd{{std::sin(M_PI * x), M_PI * std::cos(M_PI * x)}}; };
  EXPECT_LE(max_error_at(r, uniform(0, 1, 51), exact), 10 * tol * M_PI);
}

/// The same system with the batched forms of rhs and rhs_jacobian (BvpSystem::rhs_batch)
/// built from its per-point functions.
BvpSystem with_batches(BvpSystem s) {
  s.rhs_batch = [f = s.rhs](ConstVectorRef t, ConstMatrixRef y, ConstVectorRef p, MatrixRef dy) {
    for (Eigen::Index j = 0; j < t.size(); ++j) f(t[j], y.col(j), p, dy.col(j));
  };
  if (s.rhs_jacobian) {
    s.rhs_jacobian_batch = [J = s.rhs_jacobian, n = s.n, k = s.k](ConstVectorRef t, ConstMatrixRef y, ConstVectorRef p,
                                                                   MatrixRef dfdy, MatrixRef dfdp) {
      for (Eigen::Index j = 0; j < t.size(); ++j) J(t[j], y.col(j), p, dfdy.middleCols(n * j, n), dfdp.middleCols(k * j, k));
    };
  }
  return s;
}

// The batched forms only change how f and its Jacobian are called: the same mesh, iterations,
// evaluation count and solution to the last bit, with and without a parameter (dfdp batched).
TEST(Collocation, BatchedCallbacksTakeTheSamePath) {
  BvpSystem eigen;
  eigen.n = 2;
  eigen.k = 1;
  eigen.rhs = [](double, ConstVectorRef y, ConstVectorRef p, VectorRef dy) { dy << y[1], -p[0] * p[0] * y[0]; };
  eigen.rhs_jacobian = [](double, ConstVectorRef y, ConstVectorRef p, MatrixRef dfdy, MatrixRef dfdp) {
    dfdy << 0, 1, -p[0] * p[0], 0;
    dfdp << 0, -2 * p[0] * y[0];
  };
  eigen.bc = [](ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef p, VectorRef r) { r << ya[0], yb[0], ya[1] - p[0]; };
  const VectorXd t = uniform(0, 1, 6);
  MatrixXd guess(2, t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) guess.col(i) << 4 * t[i] * (1 - t[i]), 4 - 8 * t[i];
  const std::vector<std::pair<BvpSystem, VectorXd>> problems{{quadratic_problem(true), VectorXd(0)},
                                                             {quadratic_problem(false), VectorXd(0)},
                                                             {eigen, VectorXd{{2.5}}}};
  for (const auto& [system, p] : problems) {
    const MatrixXd y0 = system.k == 0 ? MatrixXd(perturbed_guess(t, quadratic_exact, 0.1)) : guess;
    const BvpResult a = solve_collocation(system, t, y0, p, {.tol = 1e-8});
    const BvpResult b = solve_collocation(with_batches(system), t, y0, p, {.tol = 1e-8});
    ASSERT_TRUE(a.success() && b.success()) << a.message << b.message;
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.p, b.p);
    EXPECT_EQ(a.newton_iterations, b.newton_iterations);
    EXPECT_EQ(a.rhs_evaluations, b.rhs_evaluations);
    EXPECT_EQ(a.rms_residual, b.rms_residual);
  }
}

/// eps y'' + t y' = -eps pi^2 cos(pi t) - pi t sin(pi t) on [-1, 1], y(-1) = -2, y(1) = 0 (SciPy's
/// shock test, after Ascher–Mattheij–Russell): y = cos(pi t) + erf(t / sqrt(2 eps)) / erf(1 / sqrt(2 eps)).
struct ShockLayer {
  double eps;
  BvpSystem system() const {
    BvpSystem s;
    s.n = 2;
    s.rhs = [e = eps](double t, ConstVectorRef y, ConstVectorRef, VectorRef dy) {
      dy << y[1], -(t * y[1] + e * M_PI * M_PI * std::cos(M_PI * t) + M_PI * t * std::sin(M_PI * t)) / e;
    };
    s.bc = [](ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef, VectorRef r) { r << ya[0] + 2, yb[0]; };
    return s;
  }
  VectorXd exact(double t) const {
    const double w = std::sqrt(2 * eps), scale = std::erf(1 / w);
    return VectorXd{{std::cos(M_PI * t) + std::erf(t / w) / scale,
                     -M_PI * std::sin(M_PI * t) + 2 / std::sqrt(M_PI) / w * std::exp(-t * t / (2 * eps)) / scale}};
  }
};

// A mildly stiff layer of width sqrt(eps) = 0.1 at t = 0 from a zero guess on 5 nodes: the
// refinement must concentrate nodes in the layer, and the error must follow the residual.
TEST(Collocation, BoundaryLayerFromZeroGuessConcentratesNodes) {
  const ShockLayer shock{1e-2};
  const double tol = 1e-6;
  const BvpResult r = solve_collocation(shock.system(), uniform(-1, 1, 5), MatrixXd::Zero(2, 5), VectorXd(0), {.tol = tol});
  ASSERT_TRUE(r.success()) << r.message;
  const auto in_layer = (r.t.array().abs() < 0.3).count();
  EXPECT_GT(in_layer, r.t.size() - in_layer) << "nodes in |t| < 0.3: " << in_layer << " of " << r.t.size();
  // y' reaches 1/sqrt(eps) ~ 8 in the layer: the residual is relative to 1 + |f| with
  // |f| ~ |y''| ~ 100 there, so errors of up to ~100 tol are what the control allows.
  const auto exact = [&](double x) { return shock.exact(x); };
  EXPECT_LE(max_error_at(r, uniform(-1, 1, 401), exact), 100 * tol);
}

// Both factorisations of the Newton matrix (structured block LU, Eigen's SparseLU) solve the
// same linear systems, so the whole adaptive run takes the same path: same mesh, same Newton
// count, solutions equal to rounding amplified by a few Newton steps (1e-10).
TEST(Collocation, BlockAndSparseLUTakeTheSamePath) {
  const ShockLayer shock{1e-2};
  BvpResult r[2];
  int j = 0;
  for (LinearSolverKind kind : {LinearSolverKind::BlockLU, LinearSolverKind::SparseLU}) {
    r[j] = solve_collocation(shock.system(), uniform(-1, 1, 5), MatrixXd::Zero(2, 5), VectorXd(0),
                             {.tol = 1e-6, .linear_solver = kind});
    ASSERT_TRUE(r[j].success()) << r[j].message;
    ++j;
  }
  ASSERT_EQ(r[0].t.size(), r[1].t.size());
  EXPECT_EQ(r[0].newton_iterations, r[1].newton_iterations);
  EXPECT_LE((r[0].y - r[1].y).cwiseAbs().maxCoeff(), 1e-10);
}

// Reusing the Newton matrix (chord steps while Newton contracts by 4 or more) changes the
// iterates but not the convergence test, so both runs meet the same residual bound: same
// accuracy against the exact solution (the error bound 100 tol of the test above), fewer
// Jacobians with reuse, and at least one chord step taken (more Newton iterations than
// Jacobians) — otherwise the option would be untested.
TEST(Collocation, ReusingTheNewtonMatrixKeepsTheAccuracyWithFewerJacobians) {
  const ShockLayer shock{1e-2};
  const auto exact = [&](double x) { return shock.exact(x); };
  BvpResult r[2];
  for (int reuse : {0, 1}) {
    r[reuse] = solve_collocation(shock.system(), uniform(-1, 1, 5), MatrixXd::Zero(2, 5), VectorXd(0),
                                 {.tol = 1e-6, .reuse_jacobian = reuse == 1});
    ASSERT_TRUE(r[reuse].success()) << r[reuse].message;
    EXPECT_LE(max_error_at(r[reuse], uniform(-1, 1, 401), exact), 100 * 1e-6) << reuse;
  }
  EXPECT_EQ(r[0].newton_iterations, r[0].jacobian_evaluations);
  EXPECT_LT(r[1].jacobian_evaluations, r[0].jacobian_evaluations);
  EXPECT_GT(r[1].newton_iterations, r[1].jacobian_evaluations);
}

// Warm start: continuing from a converged result at the same tolerance needs no Newton step and
// no new node; continuing to a tighter tolerance refines from it and reaches that tolerance.
TEST(Collocation, ContinuationFromAPreviousSolution) {
  const BvpSystem s = quadratic_problem(true);
  const VectorXd t = uniform(0, 1, 5);
  const BvpResult loose = solve_collocation(s, t, perturbed_guess(t, quadratic_exact, 0.3), VectorXd(0), {.tol = 1e-3});
  ASSERT_TRUE(loose.success()) << loose.message;
  const BvpResult again = solve_collocation(s, loose, {.tol = 1e-3});
  ASSERT_TRUE(again.success()) << again.message;
  EXPECT_EQ(again.newton_iterations, 0);
  EXPECT_EQ(again.t.size(), loose.t.size());
  const BvpResult tight = solve_collocation(s, loose, {.tol = 1e-9});
  ASSERT_TRUE(tight.success()) << tight.message;
  EXPECT_GT(tight.t.size(), loose.t.size());
  EXPECT_LE(max_error_at(tight, uniform(0, 1, 101), quadratic_exact), 1e-8);
}

// Cubic Hermite dense output reproduces cubics exactly (so S interpolates nodes and slopes).
TEST(Collocation, DenseOutputReproducesCubics) {
  const auto cubic = [](double t) { return 1 - 2 * t + 0.5 * t * t * t; };
  const auto slope = [](double t) { return -2 + 1.5 * t * t; };
  const VectorXd t{{-1.0, 0.2, 0.5, 2.0}};
  MatrixXd y(1, 4), yp(1, 4);
  for (int i = 0; i < 4; ++i) y(0, i) = cubic(t[i]), yp(0, i) = slope(t[i]);
  const CubicHermite s(t, y, yp);
  for (double x : {-1.5, -1.0, -0.3, 0.2, 0.41, 1.7, 2.0, 2.5}) {
    EXPECT_NEAR(s.value(x)[0], cubic(x), 1e-13) << x;
    EXPECT_NEAR(s.derivative(x)[0], slope(x), 1e-13) << x;
  }
}

// SciPy's refinement rule (scipy_refinement.hpp) on a cubic, which its Hermite interpolant
// reproduces: intervals with r <= tol, NaN, tol < r < 100 tol and r >= 100 tol get 0, 0, 1 (the
// middle) and 2 nodes (the thirds); the old nodes keep their values exactly, the new ones are the
// cubic to rounding (1e-13: values of order 1).
TEST(Collocation, ScipyRefinementRule) {
  const auto cubic = [](double t) { return 1 - 2 * t + 0.5 * t * t * t; };
  const auto slope = [](double t) { return -2 + 1.5 * t * t; };
  const VectorXd t{{-1.0, 0.2, 0.5, 2.0, 2.3}};
  MatrixXd y(1, 5), yp(1, 5);
  for (int i = 0; i < 5; ++i) y(0, i) = cubic(t[i]), yp(0, i) = slope(t[i]);
  const double tol = 1e-3;
  const VectorXd rms{{tol, std::nan(""), 99 * tol, 100 * tol}};
  const RefinedMesh r = scipy_refinement(CubicHermite(t, y, yp), rms, tol);
  const VectorXd expected{{-1.0, 0.2, 0.5, 1.25, 2.0, 2.1, 2.2, 2.3}};
  EXPECT_EQ(r.added, 3);
  ASSERT_EQ(r.t.size(), expected.size());
  EXPECT_LE((r.t - expected).cwiseAbs().maxCoeff(), 1e-15);
  for (Eigen::Index j = 0; j < r.t.size(); ++j) EXPECT_NEAR(r.y(0, j), cubic(r.t[j]), 1e-13) << r.t[j];
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r.y(0, i < 3 ? i : (i == 3 ? 4 : 7)), y(0, i)) << i;
  EXPECT_THROW(scipy_refinement(CubicHermite(t, y, yp), VectorXd::Zero(3), tol), std::invalid_argument);
}

// ---- Every failure status, provoked ----

TEST(CollocationStatus, MaxNodesExceeded) {
  const BvpResult r = solve_collocation(ShockLayer{1e-3}.system(), uniform(-1, 1, 5), MatrixXd::Zero(2, 5),
                                        VectorXd(0), {.tol = 1e-8, .max_nodes = 40});
  EXPECT_EQ(r.status, Status::MaxNodesExceeded) << r.message;
  EXPECT_NE(r.message.find("max_nodes = 40"), std::string::npos) << r.message;
  EXPECT_LE(r.t.size(), 40);
}

// y' = 0 with y(a) = y(b) does not determine the constant: the Jacobian is exactly singular.
TEST(CollocationStatus, SingularJacobian) {
  BvpSystem s;
  s.n = 1;
  s.rhs = [](double, ConstVectorRef, ConstVectorRef, VectorRef dy) { dy.setZero(); };
  s.bc = [](ConstVectorRef ya, ConstVectorRef yb, ConstVectorRef, VectorRef r) { r << ya[0] - yb[0]; };
  const VectorXd t = uniform(0, 1, 4);
  const BvpResult r = solve_collocation(s, t, t.transpose(), VectorXd(0));
  EXPECT_EQ(r.status, Status::SingularJacobian) << r.message;
  EXPECT_NE(r.message.find("singular"), std::string::npos) << r.message;
}

TEST(CollocationStatus, NotConvergedWhenRefinementsRunOut) {
  const BvpResult r = solve_collocation(ShockLayer{1e-2}.system(), uniform(-1, 1, 5), MatrixXd::Zero(2, 5),
                                        VectorXd(0), {.tol = 1e-8, .max_refinements = 1});
  EXPECT_EQ(r.status, Status::NotConverged) << r.message;
  EXPECT_NE(r.message.find("max_refinements = 1"), std::string::npos) << r.message;
  EXPECT_GT(r.max_rms_residual, 1e-8);
}

// One Newton iteration cannot solve the nonlinear problem from a poor guess, and halving the
// mesh (the response to a Newton failure) is blocked by max_nodes.
TEST(CollocationStatus, NotConvergedWhenNewtonFails) {
  const VectorXd t = uniform(0, 1, 5);
  const BvpResult r = solve_collocation(quadratic_problem(true), t, perturbed_guess(t, quadratic_exact, 2.0), VectorXd(0),
                                        {.tol = 1e-6, .max_nodes = 8, .max_newton_iterations = 1});
  EXPECT_EQ(r.status, Status::NotConverged) << r.message;
  EXPECT_NE(r.message.find("Newton did not converge"), std::string::npos) << r.message;
}

TEST(CollocationStatus, NotConvergedWhenRhsIsNotFinite) {
  BvpSystem s;
  s.n = 1;
  s.rhs = [](double, ConstVectorRef y, ConstVectorRef, VectorRef dy) { dy << std::sqrt(y[0]); };
  s.bc = [](ConstVectorRef ya, ConstVectorRef, ConstVectorRef, VectorRef r) { r << ya[0] - 1; };
  const BvpResult r = solve_collocation(s, uniform(0, 1, 3), MatrixXd::Constant(1, 3, -1.0), VectorXd(0));
  EXPECT_EQ(r.status, Status::NotConverged) << r.message;
  EXPECT_NE(r.message.find("not finite"), std::string::npos) << r.message;
}

// A stop (here Ctrl-C's cancel flag, raised by f itself after 1000 evaluations) during a sweep
// of f over a long mesh ends the sweep within the 256 points between two polls, and the result
// says where it stopped, with no value of an evaluation it did not finish: before, the sweeps
// over the nodes and the midpoints (40 000 points) ran to their end and Newton's first
// Jacobian's differences after them, so a stop waited on up to three sweeps of the mesh.
TEST(CollocationStatus, InterruptedWithinAFewHundredPointsOfASweep) {
  constexpr int kNodes = 20'001;
  constexpr int kRaisedAt = 1000;
  const auto flag = std::make_shared<std::atomic<bool>>(false);
  int evaluations = 0;
  BvpSystem s = quadratic_problem(false);
  const auto rhs = s.rhs;
  s.rhs = [&, rhs](double t, ConstVectorRef y, ConstVectorRef p, VectorRef dy) {
    if (++evaluations == kRaisedAt) flag->store(true);
    rhs(t, y, p, dy);
  };
  const SolveMonitor monitor = SolveMonitor().with_cancel_flag(flag);
  const VectorXd t = uniform(0, 1, kNodes);
  const BvpResult r =
      solve_collocation(s, t, perturbed_guess(t, quadratic_exact, 0.1), VectorXd(0), {.max_nodes = kNodes, .monitor = &monitor});
  EXPECT_EQ(r.status, Status::Interrupted) << r.message;
  EXPECT_NE(r.message.find("stop requested while evaluating the initial guess"), std::string::npos) << r.message;
  EXPECT_LE(evaluations - kRaisedAt, 256);
  EXPECT_TRUE(std::isnan(r.max_bc_residual)) << r.max_bc_residual;  // the boundary conditions were not evaluated
  EXPECT_EQ(r.rms_residual.size(), 0);  // nor the residuals, which need f everywhere
}

// ---- Bad input: std::invalid_argument naming the value ----

void expect_invalid(const std::function<void()>& call, const std::string& needle) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected one mentioning " << needle;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(CollocationBadInput, ThrowsNamingTheValue) {
  const BvpSystem s = quadratic_problem(false);
  const VectorXd t = uniform(0, 1, 4);
  const MatrixXd y = MatrixXd::Ones(2, 4);
  const VectorXd none(0);
  const double nan = std::nan("");
  expect_invalid([&] { solve_collocation(s, VectorXd{{0.0, nan, 1.0}}, MatrixXd::Ones(2, 3), none); }, "t = ");
  expect_invalid([&] { solve_collocation(s, VectorXd{{1.0, 0.0}}, MatrixXd::Ones(2, 2), none); },
                 "not strictly increasing");
  expect_invalid([&] { solve_collocation(s, VectorXd{{0.0, 0.5, 0.5, 1.0}}, y, none); }, "t[2] = 0.5");
  expect_invalid([&] { solve_collocation(s, VectorXd{{0.0}}, MatrixXd::Ones(2, 1), none); }, "at least 2 nodes");
  expect_invalid([&] { solve_collocation(s, t, MatrixXd::Ones(3, 4), none); }, "y = ");
  expect_invalid([&] { solve_collocation(s, t, MatrixXd::Constant(2, 4, nan), none); }, "non-finite");
  expect_invalid([&] { solve_collocation(s, t, y, VectorXd{{1.0}}); }, "p = ");
  expect_invalid([&] { solve_collocation(s, t, y, none, {.tol = 0}); }, "tol = 0");
  expect_invalid([&] { solve_collocation(s, t, y, none, {.tol = -1e-3}); }, "tol = -0.001");
  expect_invalid([&] { solve_collocation(s, t, y, none, {.tol = nan}); }, "tol = nan");
  expect_invalid([&] { solve_collocation(s, t, y, none, {.tol = 1e-17}); }, "100 machine epsilons");
  expect_invalid([&] { solve_collocation(s, t, y, none, {.max_nodes = 1}); }, "max_nodes = 1");
  expect_invalid([&] { solve_collocation(s, t, y, none, {.max_nodes = 3}); }, "max_nodes = 3");
  BvpSystem empty = s;
  empty.rhs = nullptr;
  expect_invalid([&] { solve_collocation(empty, t, y, none); }, "system.rhs");
  BvpSystem zero = s;
  zero.n = 0;
  expect_invalid([&] { solve_collocation(zero, t, MatrixXd(0, 4), none); }, "system.n = 0");
  // A value is named, never poured out: a guess of 2 x 10001 with a NaN made an 18 KB message
  // (format_value cuts after 160 characters of entries).
  const VectorXd fine = uniform(0, 1, 10001);
  MatrixXd big = MatrixXd::Ones(2, 10001);
  big(1, 5000) = nan;
  try {
    solve_collocation(s, fine, big, none, {.max_nodes = 20000});
    ADD_FAILURE() << "a NaN in y was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_LT(message.size(), 300u) << message;
    EXPECT_NE(message.find("y = [1, 1, "), std::string::npos) << message;
    EXPECT_NE(message.find("...] contains a non-finite number"), std::string::npos) << message;
  }
}

// Every kernel's start of collocation (solvers::collocate_from_mesh, src/solvers/collocation.cpp):
// Newton on the start's mesh, then refinement with both runs' counters summed; after a failure on
// the mesh, the failure itself (Report) or the adaptive solver from the same start (Adaptive):
// the same calls as made by hand, so the same results to the bit.
TEST(Collocation, TheMeshFirstStartIsNewtonOnTheMeshThenRefinement) {
  const BvpSystem s = quadratic_problem(true);
  const VectorXd t = uniform(0, 1, 5);
  const CollocationOptions options{.tol = 1e-8};
  const MatrixXd near = perturbed_guess(t, quadratic_exact, 0.05);
  const solvers::MeshFirst good = solvers::collocate_from_mesh(s, t, near, options, solvers::OnMeshFailure::Report);
  ASSERT_TRUE(good.converged_on_mesh);
  const BvpResult on_mesh = solve_collocation_on_mesh(s, t, near, VectorXd(0), options);
  const BvpResult refined = solve_collocation(s, on_mesh, options);
  ASSERT_TRUE(refined.success()) << refined.message;
  EXPECT_EQ(good.result.newton_iterations, on_mesh.newton_iterations + refined.newton_iterations);
  EXPECT_EQ(good.result.jacobian_evaluations, on_mesh.jacobian_evaluations + refined.jacobian_evaluations);
  EXPECT_EQ(good.result.t, refined.t);
  EXPECT_LE(max_error_at(good.result, uniform(0, 1, 21), quadratic_exact), 1e-6);

  // One Newton iteration cannot converge from a start this far: the mesh attempt fails.
  const CollocationOptions one{.tol = 1e-8, .max_newton_iterations = 1};
  const MatrixXd far = perturbed_guess(t, quadratic_exact, 1.0);
  const solvers::MeshFirst reported = solvers::collocate_from_mesh(s, t, far, one, solvers::OnMeshFailure::Report);
  EXPECT_FALSE(reported.converged_on_mesh);
  EXPECT_FALSE(reported.result.success());
  EXPECT_EQ(reported.result.newton_iterations, solve_collocation_on_mesh(s, t, far, VectorXd(0), one).newton_iterations);
  const solvers::MeshFirst retried = solvers::collocate_from_mesh(s, t, far, one, solvers::OnMeshFailure::Adaptive);
  const BvpResult adaptive = solve_collocation(s, t, far, VectorXd(0), one);
  EXPECT_FALSE(retried.converged_on_mesh);
  EXPECT_EQ(retried.result.status, adaptive.status);
  EXPECT_EQ(retried.result.newton_iterations, adaptive.newton_iterations);
  EXPECT_EQ(retried.result.t, adaptive.t);
}


/// The quadratic problem as a kernel's continuous problem: starts from the exact solution
/// perturbed by `start_offset` (a given trajectory or the geodesic guess, as `given` says), and
/// from a shooting result at the exact solution perturbed by 0.01.
struct QuadraticContinuous final : solvers::ContinuousProblem {
  VectorXd mesh = uniform(0, 1, 5);
  double start_offset = 1.0;
  bool given = false, on_mesh = false;
  mutable std::string shooting_seen;
  BvpSystem system() const override { return quadratic_problem(true); }
  bool start(VectorXd& t, MatrixXd& y) const override {
    t = mesh;
    y = perturbed_guess(t, quadratic_exact, start_offset);
    return given;
  }
  void start_from(solvers::PathResultPtr shooting, VectorXd& t, MatrixXd& y) const override {
    shooting_seen = shooting->core().message;
    t = mesh;
    y = perturbed_guess(t, quadratic_exact, 0.01);
  }
  bool starts_on_mesh() const override { return on_mesh; }
};

/// The discrete kernel of collocation's fallback: each method returns its scripted status (the
/// path's failure by default) with 3 sweeps, and records what it was asked.
class FallbackKernel final : public solvers::StrategyKernel {
 public:
  std::map<std::string, Status> outcome;
  std::vector<std::string> calls;
  ShootingOptions shooting_seen, path_seen;
  std::string failed_direct_seen;
  double lambda_start_seen = -1;

  solvers::PathResultPtr empty() const override { return solvers::scripted(Status::NotConverged, 0, 0, 0, 0, "", false); }
  double auxiliary_scale() const override { return 1; }
  bool guessed() const override { return false; }
  int steps() const override { return 4; }
  bool time_rescaling_invariant() const override { return false; }
  std::optional<double> lambda() const override { return 0.5; }
  bool has_collocation() const override { return true; }
  bool has_multiple_shooting() const override { return false; }
  int first_shooting_window() const override { return 7; }
  solvers::PathResultPtr shoot(const ShootingOptions& options) override {
    shooting_seen = options;
    return run("shooting");
  }
  solvers::PathResultPtr shoot_from(const ShootingOptions&, const solvers::PathResult&) override {
    return run("shoot_from");
  }
  solvers::PathResultPtr continue_in_T(const ContinuationOptions& options, solvers::PathResultPtr failed) override {
    path_seen = options.shooting;
    failed_direct_seen = failed ? failed->core().message : "none";
    return run("T");
  }
  solvers::PathResultPtr continue_in_lambda(const ContinuationOptions& options, double start) override {
    path_seen = options.shooting;
    lambda_start_seen = start;
    return run("lambda");
  }
  solvers::PathResultPtr collocate(const SolveOptions&, int) override { return run("collocate"); }
  solvers::PathResultPtr multiple_shoot(const SolveOptions&, const SolveMonitor&) override {
    return run("multiple");
  }

 private:
  solvers::PathResultPtr run(const std::string& name) {
    calls.push_back(name);
    const Status status = outcome.contains(name) ? outcome.at(name) : Status::ContinuationFailed;
    return solvers::scripted(status, status == Status::Converged ? 0.0 : 0.5, 0, 3, 2, name);
  }
};

// Collocation's driver, every kernel's (solvers::collocate): without a fallback the kernel's way
// of solving a start (adaptive, or on the mesh first); with one, Newton must converge on the
// start's mesh, else the order-2 shooting solution (shooting within the kernel's window, then
// continuation in T from that failed attempt; or continuation in lambda from 0) is the start, the
// work of every run summed; a failed fallback is a failure with its status. Compared with the same
// calls made by hand.
TEST(Collocation, TheDriverFallsBackToTheOrderTwoShootingSolution) {
  const CollocationOptions options{.tol = 1e-8, .max_newton_iterations = 3};
  QuadraticContinuous problem;
  const BvpSystem s = quadratic_problem(true);
  const MatrixXd far = perturbed_guess(problem.mesh, quadratic_exact, 1.0);
  const BvpResult failed_on_mesh = solve_collocation_on_mesh(s, problem.mesh, far, VectorXd(0), options);
  ASSERT_FALSE(failed_on_mesh.success());  // three Newton iterations do not reach the solution from 1.0 away
  const solvers::MeshFirst from_near = solvers::collocate_from_mesh(
      s, problem.mesh, perturbed_guess(problem.mesh, quadratic_exact, 0.01), options, solvers::OnMeshFailure::Adaptive);
  ASSERT_TRUE(from_near.converged_on_mesh);

  {  // no fallback: the adaptive solver, or the mesh first, from the start
    FallbackKernel discrete;
    const solvers::Collocated alone = solvers::collocate(problem, discrete, Continuation::None, options);
    const BvpResult adaptive = solve_collocation(s, problem.mesh, far, VectorXd(0), options);
    EXPECT_EQ(alone.result.status, adaptive.status);
    EXPECT_EQ(alone.result.newton_iterations, adaptive.newton_iterations);
    EXPECT_EQ(alone.branch, "direct from the geodesic guess on a uniform mesh of N intervals");
    problem.on_mesh = problem.given = true;
    const solvers::Collocated mesh_first = solvers::collocate(problem, discrete, Continuation::None, options);
    EXPECT_EQ(mesh_first.result.newton_iterations,
              solvers::collocate_from_mesh(s, problem.mesh, far, options, solvers::OnMeshFailure::Adaptive)
                  .result.newton_iterations);
    EXPECT_EQ(mesh_first.branch, "from the given trajectory");
    EXPECT_TRUE(discrete.calls.empty());
  }
  problem.on_mesh = problem.given = false;
  {  // the direct shooting converges: its solution starts collocation
    FallbackKernel discrete;
    discrete.outcome["shooting"] = Status::Converged;
    const solvers::Collocated c = solvers::collocate(problem, discrete, Continuation::T, options);
    ASSERT_TRUE(c.result.success()) << c.result.message;
    EXPECT_EQ(discrete.calls, std::vector<std::string>{"shooting"});
    EXPECT_EQ(discrete.shooting_seen.order, SchemeOrder::Second);
    EXPECT_EQ(discrete.shooting_seen.tolerance, options.tol);
    EXPECT_EQ(discrete.shooting_seen.max_iterations, options.max_newton_iterations);
    EXPECT_EQ(discrete.shooting_seen.no_progress_window, 7);  // the kernel's first window
    EXPECT_EQ(problem.shooting_seen, "shooting");
    EXPECT_EQ(c.branch,
              "from the order-2 shooting solution (direct from the geodesic guess) after Newton from the geodesic "
              "guess failed on the N-interval mesh");
    const BvpResult by_hand = solve_collocation(s, problem.mesh, perturbed_guess(problem.mesh, quadratic_exact, 0.01),
                                                VectorXd(0), options);
    EXPECT_EQ(c.result.t, by_hand.t);
    EXPECT_EQ(c.result.newton_iterations, by_hand.newton_iterations + failed_on_mesh.newton_iterations);
    EXPECT_EQ(c.result.jacobian_evaluations, by_hand.jacobian_evaluations + failed_on_mesh.jacobian_evaluations);
    EXPECT_EQ(c.shooting_sweeps, 3);
  }
  {  // the direct shooting fails: continuation in T takes it over; a given start is named
    FallbackKernel discrete;
    discrete.outcome["T"] = Status::Converged;
    problem.given = true;
    const solvers::Collocated c = solvers::collocate(problem, discrete, Continuation::T, options);
    ASSERT_TRUE(c.result.success()) << c.result.message;
    EXPECT_EQ(discrete.calls, (std::vector<std::string>{"shooting", "T"}));
    EXPECT_EQ(discrete.failed_direct_seen, "shooting");
    EXPECT_EQ(discrete.path_seen.order, SchemeOrder::Second);
    EXPECT_EQ(discrete.path_seen.no_progress_window, 0);  // the path sets its own (ContinuationOptions)
    EXPECT_EQ(problem.shooting_seen, "T");
    EXPECT_EQ(c.branch.rfind("from the order-2 shooting solution (", 0), 0u) << c.branch;
    EXPECT_NE(c.branch.find("after Newton from the given trajectory failed on its mesh"), std::string::npos) << c.branch;
    EXPECT_EQ(c.shooting_sweeps, 6);  // the direct attempt's and the path's
    problem.given = false;
  }
  {  // continuation in lambda from 0
    FallbackKernel discrete;
    discrete.outcome["lambda"] = Status::Converged;
    const solvers::Collocated c = solvers::collocate(problem, discrete, Continuation::Lambda, options);
    ASSERT_TRUE(c.result.success()) << c.result.message;
    EXPECT_EQ(discrete.calls, std::vector<std::string>{"lambda"});
    EXPECT_EQ(discrete.lambda_start_seen, 0.0);
    EXPECT_EQ(c.shooting_sweeps, 3);
  }
  {  // the fallback fails: collocation's failure on the mesh, with the path's status and words
    FallbackKernel discrete;
    const solvers::Collocated c = solvers::collocate(problem, discrete, Continuation::T, options);
    EXPECT_EQ(c.result.status, Status::ContinuationFailed);
    EXPECT_EQ(c.result.t, failed_on_mesh.t);
    EXPECT_EQ(c.result.newton_iterations, failed_on_mesh.newton_iterations);
    EXPECT_EQ(c.result.message, failed_on_mesh.message + "; the order-2 shooting fallback failed too: T");
    EXPECT_EQ(c.branch, "failed: direct from the geodesic guess on a uniform mesh of N intervals, then the order-2 "
                        "shooting fallback");
  }
  {  // Newton converges on the mesh: no fallback
    FallbackKernel discrete;
    problem.start_offset = 0.01;
    const solvers::Collocated c = solvers::collocate(problem, discrete, Continuation::T, options);
    EXPECT_TRUE(c.result.success());
    EXPECT_TRUE(discrete.calls.empty());
    EXPECT_EQ(c.shooting_sweeps, 0);
  }
}

}  // namespace
}  // namespace cartan::numerics
