// The report on a solution, every kernel's (verify/assemble.hpp).
#include "cartan/verify/assemble.hpp"

#include <algorithm>
#include <cmath>

namespace cartan::verify {

Report assemble(const Figures& f, int order, double tol, Status status) {
  Report report;
  report.order = std::min(order, 2);
  report.resolution = f.resolution;
  report.amplification = f.amplification;
  // At most 1: every figure is relative, and a threshold above 100 % says nothing. It also keeps
  // thresholds finite when absurd data (found by fuzzing: an xi of 1e215) make a overflow.
  const auto threshold = [&](double constant, int extra_power) {
    const double lambda_factor = std::pow(report.amplification, report.order + extra_power);
    const double value =
        discretisation_threshold(constant * lambda_factor, report.resolution, report.order) + threshold_floor(tol);
    return std::isfinite(value) ? std::min(value, 1.0) : 1.0;
  };
  if (status != Status::Converged) report.checks.push_back(convergence_check(status));
  report.checks.push_back({"boundary", f.boundary, tol, true, f.boundary_note});
  report.checks.push_back({"legendre", f.legendre, kLegendreThreshold, true, f.legendre_note});
  report.checks.push_back({"energy", f.energy, threshold(f.energy_constant, 1), true, f.energy_note});
  report.checks.push_back({"residual", f.residual.relative, threshold(kResidualConstant, 0), true,
                           f.residual_equations + " by finite differences, worst: " + f.residual.equation +
                               " at t = " + Report::format(f.residual.t)});
  report.checks.push_back({"stationarity", f.stationarity.value_or(0), threshold(kActionConstant, 0),
                           f.stationarity.has_value(),
                           f.stationarity ? "max |dS| / (size of its terms) over " + std::to_string(kVariations) +
                                                " random endpoint-fixed variations"
                                          : f.stationarity_note});
  return report;
}

}  // namespace cartan::verify
