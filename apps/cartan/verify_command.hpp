#pragma once
// `cartan verify`: the independent checks of include/cartan/verify/checks.hpp run on a result
// file (result_reader.hpp), each with its figure, its threshold and PASS / FAIL / N/A, and a
// verdict. docs/verify.md explains each check and where its threshold comes from.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "result_reader.hpp"

namespace cartan::cli {

struct CheckResult {
  std::string name;
  double figure = 0;     ///< the measured (dimensionless or absolute) size
  double threshold = 0;  ///< PASS when figure <= threshold
  bool applicable = true;
  std::string note;      ///< what the figure is, or why the check does not apply

  bool passed() const { return !applicable || figure <= threshold; }
  std::string verdict() const { return !applicable ? "N/A" : passed() ? "PASS" : "FAIL"; }
};

struct VerifyReport {
  double resolution = 0;  ///< h omega: the largest step times the motion's frequency
  int order = 0;          ///< the order the thresholds assume (min(file's order, 2))
  std::vector<CheckResult> checks;

  bool passed() const;
  std::string text() const;
  nlohmann::json json() const;
};

/// Runs every check on a validated result. Throws std::invalid_argument when the file's boundary
/// data or inertia are rejected by the models.
VerifyReport verify(const ResultFile& result);

}  // namespace cartan::cli
