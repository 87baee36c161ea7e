#include "collocation_command.hpp"

#include <algorithm>
#include <chrono>

#include "cartan/bvp/heisenberg_transported.hpp"
#include "cartan/bvp/transported_collocation.hpp"
#include "cartan/transported/continuation.hpp"
#include "json_rows.hpp"

namespace cartan::cli {

namespace {

/// Mesh limit of the CLI: ample for tol >= 1e-12 on the paper's problems (~1000 nodes at 1e-10
/// on H3; the SO(3) paper cases need fewer than 5000 at 1e-10).
constexpr int kMaxNodes = 20000;

bvp::CollocationOptions collocation_options(const ProblemSpec& spec) {
  return {.tol = spec.tol, .max_nodes = kMaxNodes, .max_newton_iterations = spec.max_iterations};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The output times: the final mesh, or `samples` uniform times on [0, T].
Eigen::VectorXd output_times(const ProblemSpec& spec, const bvp::BvpResult& r) {
  return spec.samples == 0 ? r.t : Eigen::VectorXd::LinSpaced(spec.samples, 0, spec.T);
}

/// What the collocation reports beyond the trajectory (which the caller adds).
nlohmann::json collocation_header(const ProblemSpec& spec, const bvp::BvpResult& r, const std::string& branch,
                                  double terminal_error, double xi_terminal, double seconds) {
  nlohmann::json out = result_header(spec, r.success() ? "converged" : std::string(bvp::to_string(r.status)), r.message,
                                     "collocation", 4, branch);
  out["terminal_error"] = terminal_error;
  out["xi_terminal"] = xi_terminal;
  out["iterations"] = {{"outer", r.refinements}, {"inner", r.newton_iterations}, {"sweeps", r.jacobian_evaluations}};
  out["mesh_size"] = r.t.size();
  out["max_residual"] = r.max_rms_residual;
  out["solve_time_s"] = seconds;
  return out;
}

/// Rows [first, first + 3) of each column, as JSON rows.
nlohmann::json column_rows(const Eigen::MatrixXd& y, Eigen::Index first) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index j = 0; j < y.cols(); ++j) out.push_back({y(first, j), y(first + 1, j), y(first + 2, j)});
  return out;
}

template <Potential<SO3> V>
nlohmann::json solve_so3(const ProblemSpec& spec, const TransportedProblem<SO3, NaturalLagrangian<SO3, V>>& problem) {
  using Collocation = bvp::TransportedCollocation<SO3, V>;
  problem.validate();
  const auto start = std::chrono::steady_clock::now();
  const bvp::CollocationOptions options = collocation_options(spec);
  const bool fallback = spec.continuation != "none";
  bvp::BvpResult r;
  if (fallback) {
    // With a fallback, Newton from the geodesic guess must first converge on the N-interval mesh;
    // otherwise the adaptive solver refines a guess outside Newton's basin up to max_nodes
    // (measured: 9 s of 10 on the T = 12 oscillator) before the fallback could start.
    Eigen::VectorXd t;
    Eigen::MatrixXd y;
    Collocation::geodesic_guess(problem, t, y);
    const bvp::BvpSystem system = Collocation::system(problem);
    r = bvp::solve_collocation_on_mesh(system, t, y, Eigen::VectorXd(0), options);
    if (r.success()) {
      const int first_iterations = r.newton_iterations, first_jacobians = r.jacobian_evaluations;
      r = bvp::solve_collocation(system, r, options);
      r.newton_iterations += first_iterations;
      r.jacobian_evaluations += first_jacobians;
    }
  } else {
    r = Collocation::solve(problem, options);
  }
  std::string branch = "direct from the geodesic guess on a uniform mesh of N intervals";
  if (!r.success() && fallback) {
    // The shooting solvers' robust path (continuation) finds a discrete solution; collocation
    // then refines its branch to the continuous solution.
    const ContinuationOptions continuation{
        .shooting = {.order = SchemeOrder::Second, .tolerance = spec.tol, .max_iterations = spec.max_iterations}};
    const TransportedSolution<SO3> s = spec.continuation == "lambda"
                                           ? solve_continuation_in_lambda(problem, 0.0, continuation)
                                           : solve_continuation_in_T(problem, continuation);
    if (s.converged) {
      Eigen::VectorXd t;
      Eigen::MatrixXd y;
      Collocation::guess_from(problem, s.trajectory, t, y);
      r = bvp::solve_collocation(Collocation::system(problem), t, y, Eigen::VectorXd(0), options);
      branch = "from the order-2 shooting solution (" + s.branch + ") after collocation from the geodesic guess failed";
    } else {
      r.message += "; the order-2 shooting fallback failed too: " + s.message;
    }
  }
  const double seconds = seconds_since(start);

  const Eigen::VectorXd t = output_times(spec, r);
  const Eigen::MatrixXd y = r.interpolant().values(t);
  std::vector<Eigen::Matrix3d> g;
  std::vector<Eigen::Vector3d> v, mu, xi;
  for (Eigen::Index j = 0; j < y.cols(); ++j) {
    g.push_back(Collocation::element(y.col(j), Collocation::kG));
    v.emplace_back(y.col(j).template segment<3>(Collocation::kV));
    xi.emplace_back(y.col(j).template segment<3>(Collocation::kXi));
    mu.push_back(problem.lagrangian.momentum(t[j], g.back(), v.back()));
  }
  double group_defect = 0;  // the exact flow stays on SO(3); collocation leaves it by its error
  for (Eigen::Index i = 0; i < r.t.size(); ++i) {
    for (int offset : {Collocation::kG, Collocation::kH}) {
      const SO3::Element m = Collocation::element(r.y.col(i), offset);
      group_defect = std::max(group_defect, (m.transpose() * m - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
    }
  }
  const Eigen::VectorXd y_end = r.y.col(r.y.cols() - 1);
  const SO3::Element g_end = Collocation::element(y_end, Collocation::kG);
  nlohmann::json out = collocation_header(spec, r, branch, SO3::log(SO3::compose(SO3::inverse(problem.gT), g_end)).norm(),
                                          y_end.template segment<3>(Collocation::kXi).norm(), seconds);
  out["t"] = std::vector<double>(t.begin(), t.end());
  out["g"] = rows(g);
  out["v"] = rows(v);
  out["mu"] = rows(mu);
  out["xi"] = rows(xi);
  out["group_defect"] = group_defect;
  return out;
}

}  // namespace

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<Heisenberg, H3Oscillator>& problem) {
  const auto start = std::chrono::steady_clock::now();
  const bvp::BvpResult r = bvp::solve_heisenberg_collocation(problem, collocation_options(spec));
  const double seconds = seconds_since(start);
  const Eigen::VectorXd t = output_times(spec, r);
  const Eigen::MatrixXd y = r.interpolant().values(t);
  Eigen::MatrixXd mu(3, y.cols());
  for (Eigen::Index j = 0; j < y.cols(); ++j) {
    mu.col(j) = problem.lagrangian.momentum(t[j], y.col(j).head<3>(), y.col(j).segment<3>(3));
  }
  const Eigen::MatrixXd xi = bvp::heisenberg_xi(problem, r, t);
  const Heisenberg::Element g_end = r.y.col(r.y.cols() - 1).head<3>();
  nlohmann::json out = collocation_header(spec, r, "direct from the geodesic guess on a uniform mesh of N intervals",
                                          Heisenberg::log(Heisenberg::compose(Heisenberg::inverse(problem.gT), g_end)).norm(),
                                          xi.col(xi.cols() - 1).norm(), seconds);
  out["t"] = std::vector<double>(t.begin(), t.end());
  out["g"] = column_rows(y, 0);
  out["v"] = column_rows(y, 3);
  out["mu"] = column_rows(mu, 0);
  out["xi"] = column_rows(xi, 0);
  return out;
}

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<SO3, RigidBody>& problem) {
  return solve_so3(spec, problem);
}

nlohmann::json solve_by_collocation(const ProblemSpec& spec, const TransportedProblem<SO3, SO3Oscillator>& problem) {
  return solve_so3(spec, problem);
}

}  // namespace cartan::cli
