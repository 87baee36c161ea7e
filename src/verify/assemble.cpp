// The report on a solution, every kernel's (verify/assemble.hpp).
#include "cartan/verify/assemble.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace cartan::verify {

Report assemble(const Figures& f, int order, double tol, Status status) {
  Report report;
  report.order = std::min(order, 2);
  report.resolution = f.resolution;
  report.amplification = f.amplification;
  // C a^q rho^p + floor; above kCoarsestThreshold (or not finite: absurd data, found by fuzzing,
  // make a overflow) the check is unresolved: not applicable, naming the threshold it would need.
  const auto threshold = [&](double constant, int extra_power) {
    const double lambda_factor = std::pow(report.amplification, report.order + extra_power);
    return discretisation_threshold(constant * lambda_factor, report.resolution, report.order) + threshold_floor(tol);
  };
  const auto discretisation_check = [&](std::string name, double figure, double limit, bool applicable, std::string note) {
    Check check{std::move(name), figure, limit, applicable, std::move(note)};
    if (applicable && !(limit <= kCoarsestThreshold)) {
      check.applicable = false;
      check.threshold = kCoarsestThreshold;
      check.note = "unresolved: figure " + Report::format(figure) + ", but at h*omega = " +
                   Report::format(report.resolution) + " its threshold would be " + Report::format(limit) + " > " +
                   Report::format(kCoarsestThreshold) +
                   ", too coarse to tell a solution from another curve (refine N or use order 2); " + check.note;
    }
    return check;
  };
  if (status != Status::Converged) report.checks.push_back(convergence_check(status));
  report.checks.push_back({"boundary", f.boundary, tol, true, f.boundary_note});
  report.checks.push_back({"legendre", f.legendre, kLegendreThreshold, true, f.legendre_note});
  report.checks.push_back(discretisation_check("energy", f.energy, threshold(f.energy_constant, 1), true, f.energy_note));
  // A check whose figure is taken by differences of the samples: its threshold adds their
  // roundoff (`floor`, relative); where that alone exceeds kCoarsestThreshold, no refinement helps.
  const auto check_above_roundoff = [&](std::string name, double figure, double limit, double floor, bool applicable,
                                        std::string note) {
    if (applicable && floor > 0.1 * limit) {  // said where it matters
      note += " (the threshold includes the samples' roundoff, " + Report::format(floor) + ")";
    }
    if (applicable && floor > kCoarsestThreshold) {
      return Check{std::move(name), figure, floor, false,
                   "unresolved: the path's steps are at the roundoff of its samples; " + note};
    }
    return discretisation_check(std::move(name), figure, limit + floor, applicable, std::move(note));
  };
  report.checks.push_back(check_above_roundoff("residual", f.residual.relative, threshold(kResidualConstant, 0),
                                               std::max(f.residual.floor, f.step_roundoff), true,
                                               f.residual_equations + " by finite differences, worst: " +
                                                   f.residual.equation + " at t = " + Report::format(f.residual.t)));
  report.checks.push_back(check_above_roundoff("stationarity", f.stationarity.value_or(0), threshold(kActionConstant, 0),
                                               f.step_roundoff, f.stationarity.has_value(),
                                               f.stationarity ? "max |dS| / (size of its terms) over " +
                                                                    std::to_string(kVariations) +
                                                                    " random endpoint-fixed variations"
                                                              : f.stationarity_note));
  const bool decided = std::any_of(report.checks.end() - 3, report.checks.end(), [](const Check& c) { return c.applicable; });
  if (!decided) {
    report.checks.push_back({"resolution", report.resolution, 0, true,
                             "no discretisation check decides at h*omega = " + Report::format(report.resolution) +
                                 " (each is unresolved or not applicable): nothing here tells a solution from another "
                                 "curve; refine N or use order 2"});
  }
  return report;
}

}  // namespace cartan::verify
