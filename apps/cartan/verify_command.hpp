#pragma once
// `cartan verify`: the library's checks and verdict (include/cartan/kernels/lie_group/verify.hpp) run on a
// result file (the library's reader, cartan/api/result_file.hpp). docs/verify.md explains each check and its threshold.

#include <nlohmann/json.hpp>

#include "cartan/api/result_file.hpp"
#include "cartan/verify/verdict.hpp"

namespace cartan::cli {

/// Runs every check on a result read by api::read_solution through the library (api::verify, cartan/api/solve.hpp,
/// which picks the checks of the kernel the connection allows); a status other than converged adds
/// the failing `converged` check. Throws std::invalid_argument when the problem is not well posed
/// (api::check: the inertia, the connection's data, the boundary data).
verify::Report verify(const api::ResultRecord& result);

/// {"verdict", "resolution", "order", "amplification", "checks": [{name, figure, threshold,
/// result, note}]}.
nlohmann::json report_json(const verify::Report& report);

}  // namespace cartan::cli
