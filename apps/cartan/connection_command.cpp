#include "connection_command.hpp"

#include "cartan/general/compiled.hpp"
#include "cartan/models/catalogue.hpp"
#include "solution_json.hpp"
#include "solve_command.hpp"

namespace cartan::cli {

namespace {

constexpr std::string_view kConnectionWhere = "cartan solve";

/// alpha_values as the nested array alpha[i][j][k].
nlohmann::json nested_alpha(const std::vector<double>& values, std::size_t n) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) {
    nlohmann::json plane = nlohmann::json::array();
    for (std::size_t j = 0; j < n; ++j) {
      plane.push_back(std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>((i * n + j) * n),
                                          values.begin() + static_cast<std::ptrdiff_t>((i * n + j + 1) * n)));
    }
    out.push_back(plane);
  }
  return out;
}

}  // namespace

nlohmann::json solve_with_connection(const ProblemSpec& spec, const SolveMonitor& monitor) {
  const models::ModelInfo& info = models::find_model(spec.group, spec.model, kConnectionWhere);
  info.check_element(spec.g0, kConnectionWhere, "g0");
  if (spec.a0.empty()) info.check_element(spec.gT, kConnectionWhere, "gT");
  return models::visit_model(spec.group, spec.model, kConnectionWhere, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    using M = manifolds::GroupManifold<G>;
    const auto problem = connection_problem<Entry>(spec, kConnectionWhere);
    transported::SolveOptions options = solve_options(spec);
    options.monitor = monitor;
    general::GeneralGuess<M> guess;
    if (!spec.v0.empty()) guess.v0 = groups::TangentOf<G>(spec.v0.data());
    const general::GeneralSolution<M> s = general::solve(problem, options, guess);
    nlohmann::json out = result_header(spec, std::string(to_string(s.status)), s.message,
                                       std::string(to_string(s.method)), s.order, s.branch);
    out["connection"] = spec.connection;
    const connections::ConnectionKind kind = connection_kind(spec);
    if (kind == connections::ConnectionKind::LeviCivita) out["metric"] = spec.metric;
    if (kind == connections::ConnectionKind::Coefficients) out["alpha"] = nested_alpha(spec.alpha_values, G::kDim);
    add_general_solution(out, s, "g");
    return out;
  });
}

}  // namespace cartan::cli
