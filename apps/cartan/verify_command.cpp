#include "verify_command.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "cartan/models/heisenberg_oscillator.hpp"
#include "cartan/models/rigid_body.hpp"
#include "cartan/verify/checks.hpp"

namespace cartan::cli {

namespace {

// Thresholds (docs/verify.md). rho = h omega is the angle one step sweeps (verify::
// TrajectoryChecks::frequency), p = min(order, 2): the order-1 scheme is O(h), the order-2 scheme
// O(h^2), and collocation output (order 4, a cubic interpolant) is checked through the same
// second-order finite differences, so O(h^2) too. Each threshold is C rho^p; C is about 7-10 times
// the largest figure / rho^p measured on honest results (free body and oscillator on SO(3) at
// T = 3, 12, 50, lambda = 0, 1/2, 1, both orders; H3 shooting and collocation):
//  * residual: central differences of forward-Euler data give (rate_{k-1} + rate_k)/2, off by
//    (h/2) rate' ~ (rho/2) x the terms' size; Heun's data and the three-point formula are off by
//    O(rho^2). Measured <= 0.15 rho (order 1), <= 0.07 rho^2 (order 2, collocation) against the
//    terms alone; adding |v| |mu| to the scale (checks.hpp) only lowers the figures (0.05 rho).
//  * stationarity: the order-p path is O(rho^p) from the stationary path of S_h and dS is linear
//    in that distance. Measured <= 0.14 rho (order 1, H3; 0.03 on SO(3)), <= 0.02 rho^2.
//  * energy: the error is O(rho^p) and measured bounded in time (0.15 rho at T = 3, 0.21 rho at
//    T = 12 for the SO(3) oscillator, no secular growth), so no factor T. Measured <= 0.48 rho
//    (order 1, H3), <= 0.015 rho^2.
// A wrong lambda, model or sample moves a figure by O(1) (tests/cli/test_verify.py).
constexpr double kResidualConstant = 1.5;
constexpr double kActionConstant = 1.0;
constexpr double kEnergyConstant = 3.0;
/// Floor of the discretisation thresholds: the solver's own tolerance (collocation's residual
/// tolerance is relative) and rounding in the differences.
double floor_of(double tol) { return 10 * tol + 1e-10; }
/// mu = dl/dv is imposed exactly by every method (natural Lagrangians: mu = I v).
constexpr double kLegendreThreshold = 1e-9;
/// Variations of the action check, and their seed (deterministic).
constexpr int kVariations = 6;
constexpr unsigned kVariationSeed = 20261122u;

template <LieGroup G>
ElementOf<G> element(const Eigen::VectorXd& x) {
  if constexpr (std::is_same_v<G, SO3>) {
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = x[i];
    return m;
  } else {
    return ElementOf<G>(x);
  }
}

template <LieGroup G>
TransportedTrajectory<G> trajectory(const ResultFile& r) {
  TransportedTrajectory<G> x;
  x.reserve(static_cast<std::size_t>(r.t.size()));
  for (Eigen::Index k = 0; k < r.t.size(); ++k) {
    x.t.push_back(r.t[k]);
    x.g.push_back(element<G>(r.g.row(k).transpose()));
    x.v.push_back(r.v.row(k).transpose());
    x.mu.push_back(r.mu.row(k).transpose());
    x.xi.push_back(r.xi.row(k).transpose());
  }
  return x;
}

std::string format(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

template <LieGroup G, ReducedLagrangian<G> L>
VerifyReport run_checks(const ResultFile& r, const L& lagrangian) {
  const verify::TrajectoryChecks<G, L> checks(lagrangian, r.lambda, r.T, trajectory<G>(r));
  VerifyReport report;
  report.order = std::min(r.order, 2);
  report.resolution = checks.max_step() * checks.frequency();
  auto threshold = [&](double constant) {
    return verify::discretisation_threshold(constant, report.resolution, report.order) + floor_of(r.tol);
  };
  report.checks.push_back({"boundary", checks.boundary_error(element<G>(r.g0), element<G>(r.gT)), r.tol, true,
                           "max(|log(g0^-1 g_0)|, |log(gT^-1 g_N)|, |xi_N|) against the file's tol"});
  report.checks.push_back({"legendre", checks.legendre_residual(), kLegendreThreshold, true,
                           "max |mu - dl/dv(g, v)|, relative"});
  report.checks.push_back({"energy", checks.energy_drift(), threshold(kEnergyConstant), true,
                           "max |E - E(0)| / max |E|, E = mu.v - l (conserved for every lambda)"});
  const verify::Residual residual = checks.equation_residual();
  report.checks.push_back({"residual", residual.relative, threshold(kResidualConstant), true,
                           "eq:reduced-system by finite differences, worst: " + residual.equation + " at t = " +
                               format(residual.t)});
  const bool uniform = verify::is_uniform(checks.trajectory().t);
  report.checks.push_back({"stationarity", uniform ? checks.action_stationarity(kVariations, kVariationSeed) : 0,
                           threshold(kActionConstant), uniform,
                           uniform ? "max |dS| / (size of its terms) over " + std::to_string(kVariations) +
                                         " random endpoint-fixed variations"
                                   : "t is not uniform (collocation with --samples 0): rerun with --samples M"});
  return report;
}

}  // namespace

bool VerifyReport::passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed(); });
}

std::string VerifyReport::text() const {
  std::ostringstream out;
  out << "resolution h*omega = " << format(resolution) << ", thresholds of order " << order << "\n";
  for (const auto& c : checks) {
    char line[64];
    std::snprintf(line, sizeof line, "%-13s %-10s <= %-10s %-4s  ", c.name.c_str(),
                  c.applicable ? format(c.figure).c_str() : "-", c.applicable ? format(c.threshold).c_str() : "-",
                  c.verdict().c_str());
    out << line << c.note << "\n";
  }
  out << "VERDICT: " << (passed() ? "PASS" : "FAIL") << "\n";
  return out.str();
}

nlohmann::json VerifyReport::json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : checks) {
    list.push_back({{"name", c.name}, {"figure", c.figure}, {"threshold", c.threshold}, {"result", c.verdict()},
                    {"note", c.note}});
  }
  return {{"verdict", passed() ? "PASS" : "FAIL"}, {"resolution", resolution}, {"order", order}, {"checks", list}};
}

VerifyReport verify(const ResultFile& r) {
  const Eigen::Matrix3d inertia = r.inertia.asDiagonal();
  if (r.group == "heisenberg") return run_checks<Heisenberg>(r, H3Oscillator(inertia));
  if (r.model == "oscillator") return run_checks<SO3>(r, SO3Oscillator(inertia));
  return run_checks<SO3>(r, RigidBody(inertia));
}

}  // namespace cartan::cli
