#pragma once
// Helpers for the mechanics tests: reference derivatives by central differences, conservation
// along a trajectory, and measured convergence orders.

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

#include "cartan/connections/cartan_schouten.hpp"
#include "cartan/mechanics/lie_group_integrator.hpp"
#include "test_support.hpp"

namespace cartan::testing {

/// A full symmetric positive-definite inertia (no principal axes along the basis), shared by the
/// mechanics tests.
inline const Eigen::Matrix3d kInertia =
    (Eigen::Matrix3d() << 2.0, 0.3, 0.1, 0.3, 3.0, -0.2, 0.1, -0.2, 4.0).finished();

/// A non-Cartan bilinear map with a symmetric part: 0.3 [u, w] + (u . A w) c + (u . w) d with A
/// symmetric, plus a non-symmetric, non-bracket part u1 w3 e.
template <groups::LieGroup G>
connections::InvariantConnection<G> non_cartan_connection(groups::Side side) {
  const Eigen::Matrix3d a = (Eigen::Matrix3d() << 1.0, 0.4, -0.2, 0.4, -0.7, 0.5, -0.2, 0.5, 0.9).finished();
  const groups::TangentOf<G> c(0.5, -1.0, 0.8), d(-0.6, 0.3, 1.1), e(0.2, 0.9, -0.4);
  return connections::InvariantConnection<G>::from_bilinear(side, [&](const groups::TangentOf<G>& u, const groups::TangentOf<G>& w) {
    return groups::TangentOf<G>(0.3 * groups::bracket<G>(u, w) + u.dot(a * w) * c + u.dot(w) * d + u[0] * w[2] * e);
  });
}

template <groups::LieGroup G>
std::vector<std::pair<std::string, connections::InvariantConnection<G>>> connections_on(groups::Side side) {
  std::vector<std::pair<std::string, connections::InvariantConnection<G>>> out;
  for (double lambda : {0.0, 0.5, 1.0}) {
    out.emplace_back("Cartan-Schouten lambda " + std::to_string(lambda), connections::cartan_schouten<G>(lambda, side));
  }
  out.emplace_back("non-Cartan", non_cartan_connection<G>(side));
  return out;
}

/// d/de f(e) at 0 by the fourth-order central difference (error ~ step^4 f^(5) + eps |f| / step).
template <class F>
auto derivative(const F& f, double step) {
  using Value = std::decay_t<decltype(f(0.0))>;
  return Value(((f(-2 * step) - f(2 * step)) + 8 * (f(step) - f(-step))) / (12 * step));
}

/// The trivialised derivative at e = 0 of a curve e -> curve(e) through at = curve(0): g^{-1} dg/de
/// (left) or dg/de g^{-1} (right), as differences of log(at^{-1} curve(e)) or log(curve(e) at^{-1})
/// (derivative above).
template <groups::LieGroup G, class Curve>
groups::TangentOf<G> trivialised_derivative(groups::Side side, const Curve& curve, double step) {
  const groups::ElementOf<G> at = curve(0.0);
  return derivative(
      [&](double e) -> groups::TangentOf<G> {
        const groups::ElementOf<G> moved = curve(e);
        return side == groups::Side::Left ? groups::log_between<G>(at, moved)
                                          : groups::TangentOf<G>(G::log(G::compose(moved, G::inverse(at))));
      },
      step);
}

/// Expects two trajectories on the same grid to agree in g and mu to `tolerance`, printing the
/// measured differences under `what`.
template <groups::LieGroup G>
void expect_same_trajectory(const std::string& what, const mechanics::Trajectory<G>& reference,
                            const mechanics::Trajectory<G>& other, double tolerance);

/// zeta_i = d/de f(exp(e E_i) g), the right-trivialised derivative of f at g (central differences).
template <groups::LieGroup G, class F>
groups::CovectorOf<G> right_gradient_fd(const F& f, const groups::ElementOf<G>& g, double step = 1e-6) {
  groups::CovectorOf<G> out;
  for (int i = 0; i < G::kDim; ++i) {
    const groups::TangentOf<G> e = groups::TangentOf<G>::Unit(i) * step;
    out[i] = (f(G::compose(G::exp(e), g)) - f(G::compose(G::exp(-e), g))) / (2 * step);
  }
  return out;
}

/// The gradient of f : R^n -> R at x (central differences), e.g. dl/dv.
template <class Vec, class F>
Vec vector_gradient_fd(const F& f, const Vec& x, double step = 1e-6) {
  Vec out;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const Vec e = Vec::Unit(x.size(), i) * step;
    out[i] = (f(Vec(x + e)) - f(Vec(x - e))) / (2 * step);
  }
  return out;
}

/// max_k |q(k) - q(0)| over the nodes of a trajectory, for a scalar quantity q of node k.
template <groups::LieGroup G>
double max_drift(const mechanics::Trajectory<G>& trajectory, const std::function<double(std::size_t)>& quantity) {
  const double q0 = quantity(0);
  double drift = 0;
  for (std::size_t k = 1; k < trajectory.t.size(); ++k) drift = std::max(drift, std::abs(quantity(k) - q0));
  return drift;
}

/// max_k |a.g[k] - b.g[k]| (entrywise) over two trajectories on the same grid.
template <groups::LieGroup G>
double max_group_difference(const mechanics::Trajectory<G>& a, const mechanics::Trajectory<G>& b) {
  double diff = 0;
  for (std::size_t k = 0; k < a.g.size(); ++k) diff = std::max(diff, max_abs_diff(a.g[k], b.g[k]));
  return diff;
}

template <groups::LieGroup G>
double max_momentum_difference(const mechanics::Trajectory<G>& a, const mechanics::Trajectory<G>& b) {
  double diff = 0;
  for (std::size_t k = 0; k < a.mu.size(); ++k) diff = std::max(diff, max_abs_diff(a.mu[k], b.mu[k]));
  return diff;
}

template <groups::LieGroup G>
void expect_same_trajectory(const std::string& what, const mechanics::Trajectory<G>& reference,
                            const mechanics::Trajectory<G>& other, double tolerance) {
  const double dg = max_group_difference(reference, other), dmu = max_momentum_difference(reference, other);
  std::cout << "[ measured ] " << what << ": max|dg| = " << dg << ", max|dmu| = " << dmu << '\n';
  EXPECT_LE(dg, tolerance) << what;
  EXPECT_LE(dmu, tolerance) << what;
}

/// Orders log2(e_k / e_{k+1}) of errors measured at step counts doubling from one to the next;
/// printed so that the test log records them.
inline std::vector<double> measured_orders(const std::string& what, const std::vector<double>& errors) {
  std::vector<double> orders;
  std::cout << "[ measured ] " << what << ": errors";
  for (double e : errors) std::cout << ' ' << e;
  std::cout << "; orders";
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
    orders.push_back(std::log2(errors[k] / errors[k + 1]));
    std::cout << ' ' << orders.back();
  }
  std::cout << '\n';
  return orders;
}

}  // namespace cartan::testing
