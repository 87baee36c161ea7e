#pragma once
// `cartan verify`: the library's checks and verdict (include/cartan/verify/report.hpp) run on a
// result file (result_reader.hpp). docs/verify.md explains each check and its threshold.

#include <nlohmann/json.hpp>

#include "cartan/verify/verdict.hpp"
#include "result_reader.hpp"

namespace cartan::cli {

/// Runs every check on a validated result through the library (api::verify, cartan/api/solve.hpp,
/// which picks the checks of the kernel the connection allows); a status other than converged adds
/// the failing `converged` check. Throws std::invalid_argument when the file's boundary data or
/// inertia are rejected by the models.
verify::Report verify(const ResultFile& result);

/// {"verdict", "resolution", "order", "amplification", "checks": [{name, figure, threshold,
/// result, note}]}.
nlohmann::json report_json(const verify::Report& report);

}  // namespace cartan::cli
