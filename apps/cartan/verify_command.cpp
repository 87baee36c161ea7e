#include "verify_command.hpp"

#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"

namespace cartan::cli {

namespace {

template <groups::LieGroup G>
groups::ElementOf<G> element(const Eigen::VectorXd& x) {
  if constexpr (std::is_same_v<G, groups::SO3>) {
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = x[i];
    return m;
  } else {
    return groups::ElementOf<G>(x);
  }
}

template <groups::LieGroup G>
transported::TransportedTrajectory<G> trajectory(const ResultFile& r) {
  transported::TransportedTrajectory<G> x;
  x.reserve(static_cast<std::size_t>(r.t.size()));
  for (Eigen::Index k = 0; k < r.t.size(); ++k) {
    x.t.push_back(r.t[k]);
    x.g.push_back(element<G>(r.g.row(k).transpose()));
    x.v.push_back(r.v.row(k).transpose());
    x.mu.push_back(r.mu.row(k).transpose());
    x.xi.push_back(r.xi.row(k).transpose());
  }
  return x;
}

template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L>
verify::Report run_checks(const ResultFile& r, const L& lagrangian) {
  const transported::TransportedProblem<G, L> problem{lagrangian, r.lambda, r.T, r.N, element<G>(r.g0), element<G>(r.gT)};
  return verify::verify_trajectory(problem, trajectory<G>(r), r.order, r.tol, parse_enum<Status>(r.status));
}

}  // namespace

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
  const Eigen::Matrix3d inertia = r.inertia.asDiagonal();
  if (r.group == "heisenberg") return run_checks<groups::Heisenberg>(r, mechanics::H3Oscillator(inertia));
  if (r.model == "oscillator") return run_checks<groups::SO3>(r, mechanics::SO3Oscillator(inertia));
  return run_checks<groups::SO3>(r, mechanics::RigidBody(inertia));
}

}  // namespace cartan::cli
