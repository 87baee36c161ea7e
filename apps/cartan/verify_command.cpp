#include "verify_command.hpp"

#include "cartan/api/solve.hpp"
#include "solve_command.hpp"

namespace cartan::cli {

nlohmann::json report_json(const verify::Report& report) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : report.checks) {
    list.push_back({{"name", c.name}, {"figure", c.figure}, {"threshold", c.threshold}, {"result", c.verdict()},
                    {"note", c.note}});
  }
  return {{"verdict", report.passed() ? "PASS" : "FAIL"}, {"resolution", report.resolution}, {"order", report.order},
          {"amplification", report.amplification}, {"checks", list}};
}

verify::Report verify(const api::ResultRecord& r) {
  constexpr std::string_view kVerifyCommandWhere = "cartan verify";
  return std::visit(
      [&](const auto& problem) {
        return api::verify(problem, r.result.samples, r.result.order, r.tol, r.result.status, kVerifyCommandWhere);
      },
      r.problem);
}

}  // namespace cartan::cli
