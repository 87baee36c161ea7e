// Golden results (docs/design/one-core.md, S0): every solver path's result recorded once, so that a
// refactor can show it changes none. Each case solves through a compiled entry point only
// (api::solve; the erased solves of kernels/lie_group/compiled.hpp and kernels/manifold/compiled.hpp where the api
// has no words for the problem), so that this unit instantiates no solver, and compares its record
// with tests/golden/<case>.json.
// CARTAN_WRITE_GOLDEN=1 writes the files instead (each test then reports itself skipped).
//
// A record: status, method, branch, order, the message with its numbers masked (each number is
// `#`) and the numbers apart, the counters, every progress report of the solve (stage, iteration,
// residual: the Levenberg–Marquardt and Newton call sequence, design §4 R3), v0 and the auxiliary
// at t = 0, the terminal errors, the action, the samples at 5 nodes, collocation's report and the
// verify report's figures. Never the solve time.
//
// Comparison: words and counters exactly. Counters, sample counts and the number of progress
// reports catch a changed call sequence that a tolerance would hide (design §4 R3, R6). Every other
// number must agree to |a - b| <= 1e-12 max(1, |a|, |b|), the design's identity threshold. The
// build has no -march, so there is no FMA contraction (R2), and one tree reproduces itself bit for
// bit. The files are the sanitizer tree's figures (clang -O1, `make build-asan`), the tree CI runs
// this test in. A GCC -O3 release tree reproduced all of them bit for bit at generation
// (tests/golden/README.md), so one tolerance serves both trees.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/api/solve.hpp"
#include "cartan/kernels/lie_group/compiled.hpp"
#include "cartan/kernels/manifold/compiled.hpp"
#include "cartan/manifolds/chart.hpp"
#include "cartan/models/catalogue.hpp"
#include "kernels/lie_group/paper_cases.hpp"

namespace cartan::testing {
namespace {

using nlohmann::json;
using transported::Continuation;
using transported::Method;
using transported::SolveOptions;

// ---- Records -----------------------------------------------------------------------------------

/// A number of a record; NaN and infinities (which JSON lacks) as the words "nan", "inf", "-inf".
json number(double x) {
  if (std::isfinite(x)) return x;
  return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
}

/// Any Eigen value's entries, row-major (as models::element_numbers writes an element).
template <class Derived>
json entries(const Eigen::DenseBase<Derived>& x) {
  json out = json::array();
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) out.push_back(number(x(i, j)));
  }
  return out;
}

/// Text with each number replaced by `#`, and the numbers: a number starts with a digit, a '.'
/// before a digit or a '-' before either, not after a letter, digit, '_' or '.'.
json masked(std::string_view s) {
  std::string text;
  json numbers = json::array();
  const auto digit = [&](std::size_t k) { return k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])); };
  std::size_t i = 0;
  while (i < s.size()) {
    const unsigned char before = i == 0 ? ' ' : static_cast<unsigned char>(s[i - 1]);
    const bool boundary = !(std::isalnum(before) || before == '_' || before == '.');
    std::size_t k = i + (s[i] == '-' ? 1 : 0);
    if (!boundary || !(digit(k) || (k < s.size() && s[k] == '.' && digit(k + 1)))) {
      text += s[i++];
      continue;
    }
    while (digit(k)) ++k;
    if (k < s.size() && s[k] == '.') {
      ++k;
      while (digit(k)) ++k;
    }
    if (k < s.size() && (s[k] == 'e' || s[k] == 'E')) {
      const std::size_t sign = k + 1 < s.size() && (s[k + 1] == '-' || s[k + 1] == '+') ? 1 : 0;
      if (digit(k + 1 + sign)) {
        k += 1 + sign;
        while (digit(k)) ++k;
      }
    }
    numbers.push_back(number(std::strtod(std::string(s.substr(i, k - i)).c_str(), nullptr)));
    text += '#';
    i = k;
  }
  return {{"text", text}, {"numbers", numbers}};
}

/// Every progress report of a solve (SolveMonitor), consecutive reports of one stage as one run.
class Progress {
 public:
  SolveMonitor monitor() {
    return SolveMonitor([this](const cartan::Progress& p) { reports_.push_back({std::string(p.stage), p.iteration, p.residual}); }, {});
  }
  json record() const {
    json runs = json::array();
    for (const Report& r : reports_) {
      if (runs.empty() || runs.back()["stage_name"] != r.stage) {
        runs.push_back({{"stage_name", r.stage}, {"stage", masked(r.stage)}, {"iteration", json::array()}, {"residual", json::array()}});
      }
      runs.back()["iteration"].push_back(r.iteration);
      runs.back()["residual"].push_back(number(r.residual));
    }
    for (json& run : runs) run.erase("stage_name");
    return runs;
  }

 private:
  struct Report {
    std::string stage;
    int iteration;
    double residual;
  };
  std::vector<Report> reports_;
};

/// The 5 nodes recorded of m samples: first, last and three between (all of them if m < 5).
std::vector<Eigen::Index> nodes(Eigen::Index m) {
  if (m < 5) {
    std::vector<Eigen::Index> all;
    for (Eigen::Index k = 0; k < m; ++k) all.push_back(k);
    return all;
  }
  return {0, (m - 1) / 4, (m - 1) / 2, 3 * (m - 1) / 4, m - 1};
}

/// Rows `at` of a table of samples.
json rows(const Eigen::MatrixXd& table, const std::vector<Eigen::Index>& at) {
  json out = json::array();
  for (Eigen::Index k : at) out.push_back(entries(table.row(k)));
  return out;
}

json report_record(const verify::Report& report) {
  json checks = json::array();
  for (const verify::Check& c : report.checks) {
    checks.push_back({{"name", c.name}, {"applicable", c.applicable}, {"passed", c.passed()}, {"figure", number(c.figure)},
                      {"threshold", number(c.threshold)}, {"note", masked(c.note)}});
  }
  return {{"resolution", number(report.resolution)}, {"order", report.order}, {"amplification", number(report.amplification)},
          {"passed", report.passed()}, {"checks", checks}};
}

/// verify's report, or the words of what it refused (e.g. a non-uniform mesh on the general kernel).
template <class F>
json verified(F&& verify) {
  try {
    return report_record(verify());
  } catch (const std::invalid_argument& e) {
    return {{"refused", masked(e.what())}};
  }
}

json collocation_record(const std::optional<transported::CollocationReport>& c) {
  if (!c) return nullptr;
  return {{"mesh_size", c->mesh_size}, {"max_residual", number(c->max_residual)}, {"group_defect", number(c->group_defect)}};
}

/// What every result has: the words, counters and terminal figures of `s` (api::Result,
/// TransportedSolution or GeneralSolution), and the samples at 5 nodes (rows of numbers).
template <class Solution>
json common_record(const Solution& s, const Eigen::VectorXd& t, const Eigen::MatrixXd& points, const Eigen::MatrixXd& v,
                   const Eigen::MatrixXd& mu, const Eigen::MatrixXd& aux) {
  const std::vector<Eigen::Index> at = nodes(t.size());
  json times = json::array();
  for (Eigen::Index k : at) times.push_back(number(t[k]));
  json index = json::array();
  for (Eigen::Index k : at) index.push_back(k);
  return {{"status", std::string(to_string(s.status))},
          {"method", std::string(to_string(s.method))},
          {"branch", s.branch},
          {"order", s.order},
          {"message", masked(s.message)},
          {"sweeps", s.sweeps},
          {"samples", t.size()},
          {"terminal_error", number(s.terminal_error)},
          {"xi_terminal", number(s.xi_terminal)},
          {"collocation", collocation_record(s.collocation)},
          {"nodes", {{"index", index}, {"t", times}, {"points", rows(points, at)}, {"v", rows(v, at)}, {"mu", rows(mu, at)},
                     {"aux", rows(aux, at)}}}};
}

/// A vector of Eigen values as rows of numbers (row-major each).
template <class Value>
Eigen::MatrixXd table(const std::vector<Value>& values) {
  if (values.empty()) return {};
  Eigen::MatrixXd out(static_cast<Eigen::Index>(values.size()), values.front().size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    const Value& x = values[k];
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      for (Eigen::Index j = 0; j < x.cols(); ++j) out(static_cast<Eigen::Index>(k), i * x.cols() + j) = x(i, j);
    }
  }
  return out;
}

Eigen::VectorXd times_of(const std::vector<double>& t) {
  return Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size()));
}

json residual_history(const std::vector<double>& history) {
  json out = json::array();
  for (double r : history) out.push_back(number(r));
  return out;
}

// ---- Cases ------------------------------------------------------------------------------------

/// One case: a name (the golden file's) and the solve that makes its record.
struct Case {
  std::string name;
  std::function<json()> record;
};

/// The api's result of `problem` with `options` (its progress recorded) and its verify report at
/// the solve's tolerance.
template <class Problem>
json api_case(const Problem& problem, SolveOptions options) {
  Progress progress;
  options.monitor = progress.monitor();
  const api::Result r = api::solve(problem, options);
  const api::Samples& x = r.samples;
  json out = common_record(r, x.t, x.points, x.v, x.mu, x.aux);
  out["entry"] = "api::solve";
  out["lie_kernel"] = r.lie_kernel;
  out["outer_iterations"] = r.outer_iterations;
  out["inner_iterations"] = r.inner_iterations;
  out["action"] = r.lie_kernel ? number(r.action) : json(nullptr);  // the general kernel computes none
  out["frame0"] = r.frame0 ? entries(*r.frame0) : json(nullptr);
  out["progress"] = progress.record();
  out["verify"] = verified([&] { return api::verify(problem, x, r.order, options.tol, r.status); });
  return out;
}

/// The compiled erased solve of the Lie-group kernel (kernels/lie_group/compiled.hpp) and its verify.
template <groups::LieGroup G>
json erased_case(const transported::ErasedProblem<G>& problem, SolveOptions options) {
  Progress progress;
  options.monitor = progress.monitor();
  const transported::TransportedSolution<G> s = transported::solve(problem, options);
  const auto& x = s.trajectory;
  json out = common_record(s, times_of(x.t), table(x.g), table(x.v), table(x.mu), table(x.xi));
  out["entry"] = "transported::solve (erased)";
  out["outer_iterations"] = s.outer_iterations;
  out["inner_iterations"] = s.inner_iterations;
  out["v0"] = entries(s.v0);
  out["xi0"] = entries(s.xi0);
  out["action"] = number(s.action);
  out["residual_history"] = residual_history(s.residual_history);
  out["progress"] = progress.record();
  out["verify"] = verified([&] { return verify::verify_solution(problem, s, options.tol); });
  return out;
}

/// The compiled general solve (kernels/manifold/compiled.hpp) and its verify.
template <class M>
json general_case(const general::ErasedProblem<M>& problem, SolveOptions options) {
  Progress progress;
  options.monitor = progress.monitor();
  const general::GeneralSolution<M> s = general::solve(problem, options);
  const auto& x = s.trajectory;
  json out = common_record(s, times_of(x.t), table(x.q), table(x.v), table(x.mu), table(x.Xi));
  out["entry"] = "general::solve (erased)";
  out["iterations"] = s.inner_iterations;
  out["v0"] = entries(s.v0);
  out["Xi0"] = entries(s.Xi0);
  out["residual_history"] = residual_history(s.residual_history);
  out["progress"] = progress.record();
  out["verify"] = verified([&] { return general::verify_general(problem, x, s.order, options.tol, s.status); });
  return out;
}

SolveOptions with_method(Method method, Continuation continuation = Continuation::None) {
  SolveOptions o;
  o.method = method;
  o.continuation = continuation;
  return o;
}

/// A built-in model by names; g0 the identity.
api::GroupProblem group(std::string name, std::string model, double lambda, double T, int N, std::vector<double> gT) {
  api::GroupProblem p;
  p.group = std::move(name);
  p.model = std::move(model);
  p.lambda = lambda;
  p.T = T;
  p.N = N;
  p.gT = std::move(gT);
  return p;
}

/// The paper's problems (tests/kernels/lie_group/paper_cases.hpp) by names and numbers.
api::GroupProblem free_body(double lambda, int N = 1000, double T = 50) {
  return group("so3", "free-rigid-body", lambda, T, N, models::element_numbers(paper_free_body(lambda, N, T).gT));
}
api::GroupProblem oscillator(double lambda, int N = 800, double T = 12) {
  return group("so3", "oscillator", lambda, T, N, models::element_numbers(paper_oscillator(lambda, N, T).gT));
}

/// A rigid motion [[R, t], [0, 1]] of SE(3) with R = exp(w), as 16 numbers.
std::vector<double> se3_element(const Eigen::Vector3d& w, const Eigen::Vector3d& t) {
  Eigen::Matrix4d g = Eigen::Matrix4d::Identity();
  g.topLeftCorner<3, 3>() = groups::SO3::exp(w);
  g.topRightCorner<3, 1>() = t;
  return models::element_numbers(g);
}

/// A rigid motion of the plane by the angle a, then t, as 9 numbers.
std::vector<double> se2_element(double a, double x, double y) {
  return {std::cos(a), -std::sin(a), x, std::sin(a), std::cos(a), y, 0, 0, 1};
}

api::ManifoldProblem quadric(std::string manifold, std::vector<double> q0, std::vector<double> qT, double gravity, double T, int N) {
  api::ManifoldProblem p;
  p.manifold = std::move(manifold);
  p.mass = {1, 2.5};
  p.gravity = gravity;
  p.q0 = std::move(q0);
  p.qT = std::move(qT);
  p.T = T;
  p.N = N;
  return p;
}

/// The paper's oscillator (lambda = 1/2 unless given) as a general problem on SO(3) with the
/// Cartan–Schouten connection: general::solve runs it on the Lie-group kernel (methods/lie_group_as_manifold.hpp).
general::ErasedProblem<manifolds::GroupManifold<groups::SO3>> cartan_schouten_oscillator(int N, double T, double lambda = 0.5) {
  using M = manifolds::GroupManifold<groups::SO3>;
  const auto p = paper_oscillator(lambda, N, T);
  return {M::cartan_schouten(lambda), general::ErasedLagrangian<M>(general::OnGroupManifold<groups::SO3, mechanics::SO3Oscillator>{p.lagrangian}),
          T, N, p.g0, p.gT, std::nullopt};
}

/// R^2 with constant Christoffel symbols (torsion and curvature) and l = 1/2 v^T diag(1, 2) v - |q|^2.
general::ErasedProblem<manifolds::Euclidean<2>> plane_problem() {
  using R2 = manifolds::Euclidean<2>;
  R2::Coefficients c;
  c[0] << 0.0, 0.3, -0.2, 0.1;
  c[1] << 0.1, 0.0, 0.2, -0.3;
  const general::KineticPotential<R2> particle(
      Eigen::Vector2d(1, 2).asDiagonal(), [](const Eigen::Vector2d& q) { return q.squaredNorm(); },
      [](const Eigen::Vector2d& q) { return Eigen::Vector2d(2 * q); });
  return {R2(c), general::ErasedLagrangian<R2>(particle), 1.3, 200, Eigen::Vector2d(0.4, -0.2), Eigen::Vector2d(-0.3, 0.5), std::nullopt};
}

/// The Poincaré half-plane as a user's chart, l = 1/2 |v|^2 in the g-orthonormal frame at q0.
general::ErasedProblem<manifolds::Chart<2>> half_plane_problem() {
  using H = manifolds::Chart<2>;
  const Eigen::Vector2d q0(-0.5, 0.8), qT(1.2, 1.6);
  return {manifolds::poincare_half_plane(), general::ErasedLagrangian<H>(general::KineticPotential<H>(Eigen::Matrix2d::Identity())),
          2.0, 100, q0, qT, Eigen::Matrix2d(q0.y() * Eigen::Matrix2d::Identity())};
}

std::vector<Case> cases() {
  std::vector<Case> out;
  const auto add = [&](std::string name, std::function<json()> record) { out.push_back({std::move(name), std::move(record)}); };
  const auto lambda_name = [](double lambda) { return lambda == 0 ? "0" : lambda == 1 ? "1" : "half"; };

  // The paper's six (tests/kernels/lie_group/paper_cases.hpp) by the default strategy; the free body
  // also by the paper's two-level scheme.
  for (double lambda : {0.0, 0.5, 1.0}) {
    add(std::string("paper_free_body_auto_lambda_") + lambda_name(lambda), [=] { return api_case(free_body(lambda), {}); });
    add(std::string("paper_oscillator_auto_lambda_") + lambda_name(lambda), [=] { return api_case(oscillator(lambda), {}); });
    add(std::string("paper_free_body_two_level_lambda_") + lambda_name(lambda),
        [=] { return api_case(free_body(lambda), with_method(Method::TwoLevel)); });
  }

  // Every explicit method on the oscillator at T = 3 (lambda = 1/2, N = 300).
  const api::GroupProblem short_oscillator = oscillator(0.5, 300, 3);
  const std::vector<std::pair<std::string, SolveOptions>> methods{
      {"shooting", with_method(Method::Shooting)},
      {"multiple_shooting", with_method(Method::MultipleShooting)},
      {"two_level", with_method(Method::TwoLevel)},
      {"variational", with_method(Method::Variational)},
      {"collocation", with_method(Method::Collocation)},
      {"shooting_continuation_T", with_method(Method::Shooting, Continuation::T)},
      {"shooting_continuation_lambda", with_method(Method::Shooting, Continuation::Lambda)},
  };
  for (const auto& method : methods) {
    add("oscillator_T3_" + method.first, [=, o = method.second] { return api_case(short_oscillator, o); });
  }
  add("oscillator_T3_shooting_order_2", [=] {
    SolveOptions o = with_method(Method::Shooting);
    o.order = SchemeOrder::Second;
    return api_case(short_oscillator, o);
  });
  // Explicit continuation in T where direct shooting fails (design §2 D7): the paper's oscillator.
  add("paper_oscillator_shooting_continuation_T_lambda_half",
      [] { return api_case(oscillator(0.5), with_method(Method::Shooting, Continuation::T)); });
  // The default strategy's later steps (bench/README.md "strategy"): continuation in lambda, the
  // collocation solution polished by shooting, multiple shooting, and the honest failure on H3
  // beyond the fold (tests/cli/test_strategy.py), which tries every step.
  const auto tolerance = [](double tol) {
    SolveOptions o;
    o.tol = tol;
    return o;
  };
  add("auto_oscillator_lambda_2_T3", [=] { return api_case(oscillator(2.0, 300, 3), tolerance(1e-8)); });
  add("auto_h3_oscillator_T5", [=] {
    return api_case(group("heisenberg", "oscillator", 0.5, 5, 500, {1, 0.5, 0.8}), tolerance(1e-8));
  });
  add("auto_se2_free_body_T_one_thousandth", [] {
    api::GroupProblem p = group("se2", "free-body", 0.5, 1e-3, 100, models::element_numbers(groups::SE2::exp({1e-3, 5e-4, 2e-3})));
    p.inertia = {1, 2, 0.5};
    return api_case(p, {});
  });
  add("failure_h3_oscillator_auto_beyond_the_fold", [=] {
    return api_case(group("heisenberg", "oscillator", 0.7, 3, 300, {1, 0.5, 0.8}), tolerance(1e-8));
  });
  // The same problem through the erased Lagrangian's compiled solve (kernels/lie_group/compiled.hpp).
  add("oscillator_T3_erased_auto", [] { return erased_case(transported::erased(paper_oscillator(0.5, 300, 3)), {}); });

  // The other groups: H3's closed-form collocation, the SE(2) and SE(3) free bodies.
  add("h3_oscillator_collocation", [] {
    return api_case(group("heisenberg", "oscillator", 0.5, 1, 100, {1, 0.5, 0.8}), with_method(Method::Collocation));
  });
  add("se2_free_body_auto", [] { return api_case(group("se2", "free-body", 0.5, 1, 100, se2_element(1.0, 1, 0.5)), {}); });
  add("se3_free_body_auto", [] {
    return api_case(group("se3", "free-body", 0.5, 1, 100, se3_element({0.5, -0.3, 0.8}, {1, -0.5, 0.7})), {});
  });

  // Failures, so that a failed result's fields are pinned too: shooting out of iterations; the
  // continuation in T of the paper's oscillator with 2 iterations a solve (tests/cli/test_strategy.py).
  add("failure_oscillator_T3_shooting_2_iterations", [=] {
    SolveOptions o = with_method(Method::Shooting);
    o.max_iterations = 2;
    return api_case(short_oscillator, o);
  });
  add("failure_paper_oscillator_continuation_T_2_iterations", [] {
    SolveOptions o = with_method(Method::Shooting, Continuation::T);
    o.max_iterations = 2;
    o.tol = 1e-6;
    return api_case(oscillator(0.5), o);
  });

  // Collocation's fallback (design §2 D15): Newton from the geodesic guess fails at T = 12, so it
  // starts from the order-2 shooting solution that continuation in T finds.
  add("paper_oscillator_collocation_continuation_T",
      [] { return api_case(oscillator(0.5), with_method(Method::Collocation, Continuation::T)); });
  // The general kernel: the quadrics (api), SO(3) with Levi-Civita and with alpha (api).
  const api::ManifoldProblem sphere = quadric("sphere", {1, 0, 0.2}, {0, 0.6, -0.8}, 3, 2, 200);
  add("sphere_auto", [=] { return api_case(sphere, {}); });
  add("sphere_collocation", [=] {
    SolveOptions o = with_method(Method::Collocation);
    o.samples = sphere.N + 1;  // uniform samples, which verify_general needs
    return api_case(sphere, o);
  });
  // At T = 6 direct shooting fails (the path in T starts at 0.75), and so does Newton from the
  // geodesic guess in collocation, whose fallback (D15) then starts from shooting continued in T.
  api::ManifoldProblem long_sphere = sphere;
  long_sphere.T = 6;
  add("sphere_shooting_continuation_T", [=] { return api_case(long_sphere, with_method(Method::Shooting, Continuation::T)); });
  add("sphere_collocation_continuation_T", [=] {
    SolveOptions o = with_method(Method::Collocation, Continuation::T);
    o.samples = long_sphere.N + 1;
    return api_case(long_sphere, o);
  });
  add("hyperbolic_plane_auto", [] { return api_case(quadric("hyperbolic-plane", {0, 0, 1}, {1.2, -0.5, 3}, 0.5, 2, 100), {}); });
  api::GroupProblem levi_civita = free_body(0.5, 200, 3);
  levi_civita.connection = connections::ConnectionKind::LeviCivita;
  levi_civita.metric = {1, 2, 3};
  add("so3_levi_civita_auto", [=] { return api_case(levi_civita, {}); });
  add("so3_levi_civita_collocation", [=] {
    SolveOptions o = with_method(Method::Collocation);
    o.samples = levi_civita.N + 1;
    return api_case(levi_civita, o);
  });
  add("so3_alpha_auto", [] {
    api::GroupProblem p = free_body(0.5, 200, 3);
    p.connection = connections::ConnectionKind::Coefficients;
    p.alpha.assign(27, 0.0);
    // alpha(e_i, e_j) = 0.3 [e_i, e_j] + 0.2 e_i delta_ij: a torsion and a symmetric part.
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      p.alpha[static_cast<std::size_t>(9 * i + 3 * j + k)] = 0.3;
      p.alpha[static_cast<std::size_t>(9 * j + 3 * i + k)] = -0.3;
      p.alpha[static_cast<std::size_t>(9 * i + 3 * i + i)] = 0.2;
    }
    return api_case(p, {});
  });

  // Cartan–Schouten through general::solve: its Lie-group kernel and that kernel's own methods.
  const std::vector<std::pair<std::string, SolveOptions>> lie_methods{
      {"auto", {}},
      {"shooting", with_method(Method::Shooting)},
      {"multiple_shooting", with_method(Method::MultipleShooting)},
      {"two_level", with_method(Method::TwoLevel)},
      {"shooting_continuation_lambda", with_method(Method::Shooting, Continuation::Lambda)},
  };
  for (const auto& method : lie_methods) {
    add("general_cartan_schouten_T3_" + method.first,
        [o = method.second] { return general_case(cartan_schouten_oscillator(300, 3), o); });
  }
  add("general_cartan_schouten_paper_oscillator_continuation_T", [] {
    return general_case(cartan_schouten_oscillator(800, 12), with_method(Method::Shooting, Continuation::T));
  });

  // R^2 with torsion and curvature, a user's chart, and a general default strategy that fails.
  add("general_plane_auto", [] { return general_case(plane_problem(), {}); });
  add("general_half_plane_chart_auto", [] { return general_case(half_plane_problem(), {}); });
  add("failure_sphere_auto_1_iteration", [=] {
    SolveOptions o;
    o.max_iterations = 1;
    return api_case(sphere, o);
  });
  return out;
}

// ---- Comparison ---------------------------------------------------------------------------------

/// The identity threshold of design §4: |a - b| <= kTolerance max(1, |a|, |b|).
constexpr double kTolerance = 1e-12;

/// The largest scaled difference |a - b| / max(1, |a|, |b|) seen per field (its key), over the run.
std::map<std::string, double>& largest_differences() {
  static std::map<std::string, double> largest;
  return largest;
}

/// Every difference between `want` (the golden record) and `got`, by path: types, keys, sizes,
/// strings, booleans and integers exactly; floating-point numbers to kTolerance.
void compare(const json& want, const json& got, const std::string& path, const std::string& field,
             std::vector<std::string>& differences) {
  const auto differ = [&](const std::string& what) { differences.push_back(path + ": " + what); };
  if (want.is_number_float() && got.is_number_float()) {
    const double a = want.get<double>(), b = got.get<double>();
    const double scaled = std::abs(a - b) / std::max({1.0, std::abs(a), std::abs(b)});
    double& largest = largest_differences()[field];
    largest = std::max(largest, scaled);
    if (!(scaled <= kTolerance)) {
      std::ostringstream out;
      out.precision(17);
      out << "golden " << a << ", now " << b << " (scaled difference " << scaled << ")";
      differ(out.str());
    }
    return;
  }
  if (want.is_number_integer() && got.is_number_integer()) {  // signed or unsigned: JSON's parse makes 3 unsigned
    if (want != got) differ("golden " + want.dump() + ", now " + got.dump());
    return;
  }
  if (want.type() != got.type()) return differ("golden " + want.dump() + ", now " + got.dump());
  if (want.is_object()) {
    for (const auto& [key, value] : want.items()) {
      if (!got.contains(key)) {
        differ("golden has " + key + ", now missing");
      } else {
        compare(value, got[key], path + "." + key, key, differences);
      }
    }
    for (const auto& [key, value] : got.items()) {
      if (!want.contains(key)) differ("now has " + key + ", golden does not");
    }
    return;
  }
  if (want.is_array()) {
    if (want.size() != got.size()) {
      return differ("golden has " + std::to_string(want.size()) + " entries, now " + std::to_string(got.size()));
    }
    for (std::size_t k = 0; k < want.size(); ++k) compare(want[k], got[k], path + "[" + std::to_string(k) + "]", field, differences);
    return;
  }
  if (want != got) differ("golden " + want.dump() + ", now " + got.dump());
}

std::string golden_path(const std::string& name) { return std::string(CARTAN_GOLDEN_DIR) + "/" + name + ".json"; }

/// The first line of a shell command's output (git's), or "" if it fails.
std::string command_line(const std::string& command) {
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    if (std::fgets(buffer, sizeof buffer, pipe)) out = buffer;
    pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

/// Where a golden file came from: the commit of the library (and whether include/ or src/ had
/// changes not committed), the compiler of this unit and a note on how to regenerate.
json provenance() {
  const std::string git = "git -C \"" + std::string(CARTAN_SOURCE_DIR) + "\" ";
  const std::string commit = command_line(git + "rev-parse HEAD 2>/dev/null");
  const bool modified = !command_line(git + "status --porcelain -- include src 2>/dev/null").empty();
#if defined(__clang__)
  std::string compiler = "clang " __clang_version__;
#else
  std::string compiler = "gcc " __VERSION__;
#endif
  while (compiler.back() == ' ') compiler.pop_back();
#if defined(__SANITIZE_ADDRESS__)
  const bool sanitized = true;
#elif defined(__has_feature)
  const bool sanitized = __has_feature(address_sanitizer);
#else
  const bool sanitized = false;
#endif
  return {{"commit", commit.empty() ? "unknown" : commit},
          {"library_modified_since_commit", modified},
          {"compiler", compiler + (sanitized ? ", AddressSanitizer" : "")},
          {"generated_by", "CARTAN_WRITE_GOLDEN=1 test_golden (tests/golden/test_golden.cpp); compared: \"result\""}};
}

bool writing() {
  const char* value = std::getenv("CARTAN_WRITE_GOLDEN");
  return value != nullptr && std::string_view(value) == "1";
}

void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

class Golden : public ::testing::TestWithParam<Case> {};

TEST_P(Golden, ResultIsUnchanged) {
  const Case& c = GetParam();
  const json got = c.record();
  const std::string path = golden_path(c.name);
  if (writing()) {
    std::ofstream file(path);
    ASSERT_TRUE(file) << "cannot write " << path;
    file << json{{"case", c.name}, {"provenance", provenance()}, {"result", got}}.dump(1) << "\n";
    GTEST_SKIP() << "CARTAN_WRITE_GOLDEN=1: wrote " << path << " (not compared)";
  }
  std::ifstream file(path);
  ASSERT_TRUE(file) << "no golden file " << path << " (generate it with CARTAN_WRITE_GOLDEN=1)";
  const json golden = json::parse(file);
  std::vector<std::string> differences;
  compare(golden.at("result"), got, c.name, "", differences);
  std::string listed;
  for (std::size_t k = 0; k < differences.size() && k < 20; ++k) listed += "\n  " + differences[k];
  EXPECT_TRUE(differences.empty()) << differences.size() << " differences from " << path << " (generated at "
                                   << golden.at("provenance").dump() << "):" << listed;
}

std::string case_name(const ::testing::TestParamInfo<Case>& c) { return c.param.name; }
INSTANTIATE_TEST_SUITE_P(Cases, Golden, ::testing::ValuesIn(cases()), case_name);

/// Prints the largest scaled difference per field at the end of a comparing run (the figures the
/// tolerance is judged by; tests/golden/README.md).
class DifferenceSummary : public ::testing::Environment {
 public:
  void TearDown() override {
    if (writing() || largest_differences().empty()) return;
    std::printf("[ golden   ] largest |a - b| / max(1, |a|, |b|) per field:");
    for (const auto& [field, value] : largest_differences()) std::printf(" %s %.3g;", field.c_str(), value);
    std::printf("\n");
  }
};
[[maybe_unused]] const auto* const summary = ::testing::AddGlobalTestEnvironment(new DifferenceSummary);

}  // namespace
}  // namespace cartan::testing
