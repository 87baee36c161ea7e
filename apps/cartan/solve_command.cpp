#include "solve_command.hpp"

#include <cmath>
#include <utility>

#include "cartan/api/result_file.hpp"
#include "cartan/models/catalogue.hpp"

namespace cartan::cli {

namespace {
constexpr std::string_view kSolveCommandWhere = "cartan solve";
}  // namespace

cartan::SolveOptions solve_options(const ProblemSpec& spec) {
  cartan::OptionWords words;
  words.method = spec.method;
  words.continuation = spec.continuation;
  words.order = spec.order;
  words.tol = spec.tol;
  words.max_iterations = spec.max_iterations;
  if (spec.segments > 0) words.segments = spec.segments;  // 0: the default
  words.samples = spec.samples;
  if (spec.time_limit > 0) words.time_limit = spec.time_limit;  // 0: no limit
  return cartan::solve_options(words, kSolveCommandWhere);
}

SO3Endpoints so3_endpoints(const ProblemSpec& spec) {
  const models::ModelInfo& model = models::find_model(spec.group, spec.model, kSolveCommandWhere);
  model.check_element(spec.g0, kSolveCommandWhere, "g0");
  if (spec.a0.empty()) model.check_element(spec.gT, kSolveCommandWhere, "gT");
  return {models::element_of<groups::SO3>(spec.g0), models::element_of<groups::SO3>(final_element(spec))};
}

nlohmann::json solve(const ProblemSpec& spec, const SolveMonitor& monitor) {
  cartan::SolveOptions options = solve_options(spec);
  options.monitor = monitor;
  const api::Guess guess = guess_of(spec);
  return result_json(spec, is_manifold_problem(spec) ? api::solve(manifold_problem(spec), options, guess, kSolveCommandWhere)
                                                     : api::solve(group_problem(spec), options, guess, kSolveCommandWhere));
}

nlohmann::json result_json(const ProblemSpec& spec, api::Result r) {
  if (r.status == Status::Interrupted) return {{"status", to_string(r.status)}};  // never written (exit 130)
  api::ResultRecord record;
  if (is_manifold_problem(spec)) record.problem = manifold_problem(spec);
  else record.problem = group_problem(spec);
  record.tol = spec.tol;
  record.result = std::move(r);  // the solve's own samples, not a copy
  return api::result_json(record);
}

}  // namespace cartan::cli
