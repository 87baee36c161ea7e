#pragma once
// The pieces both verifiers' checks share (kernels/lie_group/verify_checks.hpp on the transported problem,
// kernels/manifold/verify.hpp on a manifold): relative figures, the three-point derivative on any mesh, and
// the discretisation threshold's form (verify/verdict.hpp chooses the constants).

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace cartan::verify {

/// The largest relative residual of one equation and where it occurs.
struct Residual {
  double relative = 0;   ///< max_k |residual_k| / (the equation's term scale)
  std::string equation;  ///< which equation (g, mu, xi)
  double t = 0;          ///< where the maximum is
};

/// |a| / scale, with 0/0 = 0 (a residual is at most the sum of its terms, so this is in [0, 1]).
inline double relative_to(double a, double scale) { return scale > 0 ? a / scale : 0.0; }

/// True when t is uniform to 1e-9 of its span (the shooting methods' output).
inline bool is_uniform(const std::vector<double>& t) {
  if (t.size() < 2) return false;
  const double span = t.back() - t.front(), h = span / static_cast<double>(t.size() - 1);
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (std::abs(t[k] - (t.front() + static_cast<double>(k) * h)) > 1e-9 * span) return false;
  }
  return true;
}

/// Why action stationarity is not applicable to samples at non-uniform times (a collocation
/// solution on its own mesh): the discrete action S_h is defined on a uniform grid.
inline constexpr std::string_view kNonUniformStationarityNote =
    "t is not uniform (collocation on its own mesh): sample it uniformly (samples = M)";

/// Threshold of a discretisation error of order p at resolution rho = h omega (radians per step):
/// constant * rho^p. The constants are chosen in verify/verdict.hpp from measured margins.
inline double discretisation_threshold(double constant, double resolution, int order) {
  return constant * std::pow(resolution, order);
}

/// Weights of the three-point derivative at t_k from t_{k-1}, t_k, t_{k+1} (second order on any
/// mesh): f'(t_k) ~ a f_{k-1} + b f_k + c f_{k+1}.
struct ThreePoint {
  double a, b, c;
  ThreePoint(double h1, double h2)
      : a(-h2 / (h1 * (h1 + h2))), b((h2 - h1) / (h1 * h2)), c(h1 / (h2 * (h1 + h2))) {}
};

}  // namespace cartan::verify
