#include "collocation_command.hpp"

#include <chrono>

#include "cartan/bvp/heisenberg_transported.hpp"

namespace cartan::cli {

namespace {

/// Mesh limit of the CLI: ample for tol >= 1e-12 on the paper's H3 problems (~1000 nodes at 1e-10).
constexpr int kMaxNodes = 20000;

/// Rows [first, first + 3) of each column, as JSON rows.
nlohmann::json column_rows(const Eigen::MatrixXd& y, Eigen::Index first) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index j = 0; j < y.cols(); ++j) out.push_back({y(first, j), y(first + 1, j), y(first + 2, j)});
  return out;
}

}  // namespace

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<Heisenberg, H3Oscillator>& problem) {
  const auto start = std::chrono::steady_clock::now();
  const bvp::BvpResult r = bvp::solve_heisenberg_collocation(
      problem, {.tol = spec.tol, .max_nodes = kMaxNodes, .max_newton_iterations = spec.max_iterations});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Eigen::VectorXd t = spec.samples == 0 ? r.t : Eigen::VectorXd::LinSpaced(spec.samples, 0, spec.T);
  const Eigen::MatrixXd y = r.interpolant().values(t);
  Eigen::MatrixXd mu(3, y.cols());
  for (Eigen::Index j = 0; j < y.cols(); ++j) {
    mu.col(j) = problem.lagrangian.momentum(t[j], y.col(j).head<3>(), y.col(j).segment<3>(3));
  }
  const Eigen::MatrixXd xi = bvp::heisenberg_xi(problem, r, t);
  const Heisenberg::Element g_end = r.y.col(r.y.cols() - 1).head<3>();
  nlohmann::json out =
      result_header(spec, r.success() ? "converged" : std::string(bvp::to_string(r.status)), r.message, "collocation",
                    4, "direct from the geodesic guess on a uniform mesh of N intervals");
  out["t"] = std::vector<double>(t.begin(), t.end());
  out["g"] = column_rows(y, 0);
  out["v"] = column_rows(y, 3);
  out["mu"] = column_rows(mu, 0);
  out["xi"] = column_rows(xi, 0);
  out["terminal_error"] = Heisenberg::log(Heisenberg::compose(Heisenberg::inverse(problem.gT), g_end)).norm();
  out["xi_terminal"] = xi.col(xi.cols() - 1).norm();
  out["iterations"] = {{"outer", r.refinements}, {"inner", r.newton_iterations}, {"sweeps", r.jacobian_evaluations}};
  out["mesh_size"] = r.t.size();
  out["max_residual"] = r.max_rms_residual;
  out["solve_time_s"] = seconds;
  return out;
}

}  // namespace cartan::cli
