#pragma once
// Helpers for the mechanics tests: reference derivatives by central differences, conservation
// along a trajectory, and measured convergence orders.

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "cartan/mechanics/lie_group_integrator.hpp"
#include "test_support.hpp"

namespace cartan::testing {

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
