#include "problems.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "cartan/errors.hpp"

namespace cartan::api::detail {

namespace {

/// Throws "<where>: <name> = <value> must have <sizes>" unless x has one of the sizes.
void require_sizes(std::string_view where, const char* name, const std::vector<double>& x, std::size_t size,
                   std::size_t other, const std::string& what) {
  if (x.size() == size || x.size() == other) return;
  throw_invalid(where, name, excerpt(x),
                "must have " + std::to_string(size) + (other == size ? "" : " or " + std::to_string(other)) + " numbers (" +
                    what + ")");
}

/// A point of S^2 from 3 finite numbers, not 0, normalised.
Eigen::Vector3d sphere_point(const std::vector<double>& x, const char* name, std::string_view where) {
  require_sizes(where, name, x, 3, 3, "a point x,y,z of the sphere");
  for (double c : x) {
    if (!std::isfinite(c)) throw_invalid(where, name, excerpt(x), "contains a non-finite number");
  }
  const Eigen::Vector3d p(x.data());
  if (!(p.stableNorm() > 0)) throw_invalid(where, name, excerpt(x), "has zero length");
  return p.stableNormalized();
}

}  // namespace

CheckedGroupProblem check(const GroupProblem& problem, std::string_view where) {
  using connections::ConnectionKind;
  CheckedGroupProblem out;
  out.model = &models::find_model(problem.group, problem.model, where);
  const models::ModelInfo& model = *out.model;
  const auto n = static_cast<std::size_t>(model.dim);
  const std::string of_group = "for group " + std::string(model.group);
  out.inertia = problem.inertia.empty() ? model.default_inertia : problem.inertia;
  require_sizes(where, "inertia", out.inertia, n, n * n, "the diagonal or the matrix, row-major, " + of_group);
  models::check_inertia(model, out.inertia, where);
  if (problem.connection != ConnectionKind::LeviCivita && !problem.metric.empty()) {
    throw_invalid(where, "metric", excerpt(problem.metric), "is an option of connection levi-civita only");
  }
  if (problem.connection != ConnectionKind::Coefficients && !problem.alpha.empty()) {
    throw_invalid(where, "alpha", excerpt(problem.alpha), "is an option of connection coefficients only");
  }
  if (problem.connection == ConnectionKind::LeviCivita && !problem.metric.empty()) {
    require_sizes(where, "metric", problem.metric, n, n * n, "the diagonal or the matrix, row-major, " + of_group);
  }
  if (problem.connection == ConnectionKind::Coefficients) {
    require_sizes(where, "alpha", problem.alpha, n * n * n, n * n * n, "alpha[i][j][k] in (i, j, k) order, " + of_group);
  }
  out.g0 = problem.g0.empty() ? model.identity : problem.g0;
  const std::string element = std::string(model.element_what);
  require_sizes(where, "g0", out.g0, model.element_size, model.element_size, element);
  if (problem.gT.empty()) throw_invalid(where, "gT", "(missing)", "is required");
  require_sizes(where, "gT", problem.gT, model.element_size, model.element_size, element);
  model.check_element(out.g0, where, "g0");
  model.check_element(problem.gT, where, "gT");
  return out;
}

general::ErasedProblem<manifolds::Sphere> sphere_problem(const SphereProblem& problem, std::string_view where) {
  require_sizes(where, "mass", problem.mass, 2, 2, "a1,a2");
  for (double a : problem.mass) {
    if (!(std::isfinite(a) && a > 0)) throw_invalid(where, "mass", excerpt(problem.mass), "must be positive and finite");
  }
  require_finite(problem.gravity, where, "gravity");
  const Eigen::Vector3d q0 = sphere_point(problem.q0, "q0", where), qT = sphere_point(problem.qT, "qT", where);
  if (q0.cross(qT).norm() < 1e-12) {
    throw_invalid(where, "q0/qT", excerpt(problem.q0) + " / " + excerpt(problem.qT),
                  q0.dot(qT) > 0 ? "are equal: the frame's e1 (towards qT along the minimal great circle) is undefined"
                                 : "are antipodal: the minimal great circle is not unique");
  }
  manifolds::Sphere::Frame frame;
  frame.col(0) = (qT - q0.dot(qT) * q0).normalized();  // along the minimal great circle
  frame.col(1) = q0.cross(Eigen::Vector3d(frame.col(0)));
  using Particle = general::KineticPotential<manifolds::Sphere>;
  const Particle particle = Particle::with_linear_potential(Eigen::Vector2d(problem.mass[0], problem.mass[1]).asDiagonal(),
                                                            Eigen::Vector3d(0, 0, problem.gravity));
  return {manifolds::Sphere{}, general::ErasedLagrangian<manifolds::Sphere>(particle), problem.T, problem.N, q0, qT, frame};
}

void check_guess(const Guess& guess, int n, bool lie_kernel, std::string_view where) {
  const auto size = static_cast<std::size_t>(n);
  if (!guess.v0.empty()) require_sizes(where, "v0", guess.v0, size, size, "a guess of v(0)");
  if (guess.xi0.empty()) return;
  if (!lie_kernel) {
    throw_invalid(where, "xi0", excerpt(guess.xi0),
                  "is a guess of the Lie-group kernel's xi (a Cartan-Schouten connection), not of the general solver's Xi");
  }
  require_sizes(where, "xi0", guess.xi0, size, size, "a guess of xi(0)");
}

}  // namespace cartan::api::detail
