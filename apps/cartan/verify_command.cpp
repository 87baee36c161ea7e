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

verify::Report verify(const ResultFile& r) {
  constexpr std::string_view kVerifyCommandWhere = "cartan verify";
  const ProblemSpec& p = r.problem;
  const Status status = parse_enum<Status>(r.status);
  const api::Samples samples{r.t, r.g, r.v, r.mu, r.general() ? r.Xi : r.xi};
  if (is_manifold_problem(p)) return api::verify(manifold_problem(p), samples, r.order, p.tol, status, kVerifyCommandWhere);
  return api::verify(group_problem(p), samples, r.order, p.tol, status, kVerifyCommandWhere);
}

}  // namespace cartan::cli
