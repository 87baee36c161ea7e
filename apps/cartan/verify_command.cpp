#include "verify_command.hpp"

#include "cartan/general/compiled.hpp"
#include "cartan/transported/compiled.hpp"
#include "connection_command.hpp"
#include "manifold_command.hpp"
#include "cartan/models/catalogue.hpp"

namespace cartan::cli {

namespace {

constexpr std::string_view kVerifyCommandWhere = "cartan verify";

/// A row of numbers as the group element it writes (not projected: the checks see the file's data).
template <groups::LieGroup G>
groups::ElementOf<G> element(const Eigen::VectorXd& x) {
  if constexpr (std::is_same_v<G, groups::Heisenberg>) {
    return groups::ElementOf<G>(x);
  } else {
    constexpr int size = groups::ElementOf<G>::RowsAtCompileTime;
    return Eigen::Map<const Eigen::Matrix<double, size, size, Eigen::RowMajor>>(x.data());
  }
}

template <groups::LieGroup G>
groups::ElementOf<G> element(const std::vector<double>& x) {
  return element<G>(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()))));
}

template <groups::LieGroup G>
transported::TransportedTrajectory<G> trajectory(const ResultFile& r) {
  transported::TransportedTrajectory<G> x;
  x.reserve(static_cast<std::size_t>(r.t.size()));
  for (Eigen::Index k = 0; k < r.t.size(); ++k) {
    x.t.push_back(r.t[k]);
    x.g.push_back(element<G>(Eigen::VectorXd(r.g.row(k).transpose())));
    x.v.push_back(r.v.row(k).transpose());
    x.mu.push_back(r.mu.row(k).transpose());
    x.xi.push_back(r.xi.row(k).transpose());
  }
  return x;
}

/// The rows of a general result (t, points, v, mu, Xi row-major) as the general solver's trajectory.
template <manifolds::ManifoldWithConnection M, class Point>
general::GeneralTrajectory<M> general_trajectory(const ResultFile& r, Point point) {
  general::GeneralTrajectory<M> x;
  for (Eigen::Index k = 0; k < r.t.size(); ++k) {
    x.t.push_back(r.t[k]);
    x.q.push_back(point(Eigen::VectorXd(r.g.row(k).transpose())));
    x.v.push_back(r.v.row(k).transpose());
    x.mu.push_back(r.mu.row(k).transpose());
    manifolds::ComponentMatrixOf<M> xi;
    for (int a = 0; a < M::kDim; ++a) {
      for (int b = 0; b < M::kDim; ++b) xi(a, b) = r.Xi(k, a * M::kDim + b);
    }
    x.Xi.push_back(xi);
  }
  return x;
}

/// The general solver's results: --manifold sphere, or a group with another connection.
verify::Report verify_general_result(const ResultFile& r) {
  const ProblemSpec& p = r.problem;
  const Status status = parse_enum<Status>(r.status);
  if (is_manifold_problem(p)) {
    const auto x = general_trajectory<manifolds::Sphere>(r, [](const Eigen::VectorXd& q) { return Eigen::Vector3d(q); });
    return general::verify_general(sphere_problem(p), x, r.order, p.tol, status);
  }
  return models::visit_model(p.group, p.model, kVerifyCommandWhere, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    const auto x = general_trajectory<manifolds::GroupManifold<G>>(r, [](const Eigen::VectorXd& g) { return element<G>(g); });
    return general::verify_general(connection_problem<Entry>(p, kVerifyCommandWhere), x, r.order, p.tol, status);
  });
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
  if (r.general()) return verify_general_result(r);
  const ProblemSpec& p = r.problem;
  return models::visit_model(p.group, p.model, kVerifyCommandWhere, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    const transported::TransportedProblem<G, typename Entry::Lagrangian> problem{
        models::make_lagrangian<Entry>(p.inertia, kVerifyCommandWhere), p.lambda, p.T, p.N, element<G>(p.g0), element<G>(p.gT)};
    // Behind the erased Lagrangian, whose verify the library compiles: the model's own members
    // evaluated, so the figures of the typed verify (tests/transported/test_erased.cpp).
    return verify::verify_trajectory(transported::erased(problem), trajectory<G>(r), r.order, p.tol,
                                     parse_enum<Status>(r.status));
  });
}

}  // namespace cartan::cli
