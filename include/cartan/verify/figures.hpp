#pragma once
// The pieces both verifiers' checks share (kernels/lie_group/verify_checks.hpp on the transported problem,
// kernels/manifold/verify.hpp on a manifold): relative figures, the three-point derivative on any mesh, and
// the discretisation threshold's form (verify/verdict.hpp chooses the constants).

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace cartan::verify {

/// The largest relative residual of one equation and where it occurs.
struct Residual {
  double relative = 0;   ///< max_k |residual_k| / (the equation's term scale)
  std::string equation;  ///< which equation (g, mu, xi)
  double t = 0;          ///< where the maximum is
  /// The relative residual roundoff alone can give there (three_point_roundoff over the same
  /// scale), added to the threshold: on a path whose steps are a few ulps of its points' size
  /// (endpoints 1e-8 apart on the unit sphere), a derivative by differences is that much off.
  double floor = 0;
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

/// The roundoff each sample carries, relative to its size: a few units in the last place from the
/// step that made it (an exponential, a projection back onto the manifold, a difference).
inline constexpr double kSampleRoundoff = 4 * std::numeric_limits<double>::epsilon();

/// What the three-point formula makes of samples of sizes s_{k-1}, s_k, s_{k+1} (norms) that carry
/// kSampleRoundoff of their size each: the derivative's roundoff floor.
inline double three_point_roundoff(const ThreePoint& d, double s0, double s1, double s2) {
  return kSampleRoundoff * (std::abs(d.a) * s0 + std::abs(d.b) * s1 + std::abs(d.c) * s2);
}

/// The relative roundoff of a first variation taken from the samples (the discrete action's
/// difference quotients): kSampleRoundoff of the samples' size against the longest step between
/// two of them, twice (both ends of a step); 0 for a path that does not move.
inline double step_roundoff(double largest_sample, double longest_step) {
  return longest_step > 0 ? 2 * kSampleRoundoff * largest_sample / longest_step : 0.0;
}

/// The worst equation of `count` (0 = the first, kept unless another exceeds its floor by more):
/// largest relative residual beyond its roundoff floor.
inline Residual worst_equation(const double* worst, const double* scale, const double* noise, const double* where,
                               const char* const* names, int count) {
  Residual out;
  double margin = 0;
  for (int i = 0; i < count; ++i) {
    const double r = relative_to(worst[i], scale[i]), floor = relative_to(noise[i], scale[i]);
    if (i == 0 || r - floor > margin) out = {r, names[i], where[i], floor}, margin = r - floor;
  }
  return out;
}

}  // namespace cartan::verify
