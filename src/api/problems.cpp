#include "problems.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <cmath>

#include "cartan/errors.hpp"

namespace cartan::api::detail {

namespace {

/// Throws "<where>: <name> = <value> must have <size> numbers (<what>)" unless x has that many,
/// and "... contains a non-finite number" unless they are finite.
void require_numbers(std::string_view where, const char* name, const std::vector<double>& x, std::size_t size,
                     const std::string& what) {
  if (x.size() != size) throw_invalid(where, name, excerpt(x), "must have " + std::to_string(size) + " numbers (" + what + ")");
  for (double c : x) {
    if (!std::isfinite(c)) throw_invalid(where, name, excerpt(x), "contains a non-finite number");
  }
}

/// A symmetric matrix of the algebra given as n numbers (its diagonal) or n^2 (row-major): the
/// sizes, then finiteness.
void require_matrix_numbers(std::string_view where, const char* name, const std::vector<double>& x, std::size_t n,
                            std::string_view group) {
  if (x.size() != n && x.size() != n * n) {
    throw_invalid(where, name, excerpt(x),
                  "must have " + std::to_string(n) + " numbers (the diagonal) or " + std::to_string(n * n) +
                      " (the matrix, row-major) for group " + std::string(group));
  }
  require_numbers(where, name, x, x.size(), "");
}

/// The metric of a Levi-Civita connection: symmetric (to 1e-12 of its largest entry) and positive definite.
void require_metric(std::string_view where, const std::vector<double>& metric, Eigen::Index n) {
  const bool diagonal = metric.size() == static_cast<std::size_t>(n);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!diagonal) m(i, j) = metric[static_cast<std::size_t>(i * n + j)];
    }
    if (diagonal) m(i, i) = metric[static_cast<std::size_t>(i)];
  }
  const double scale = m.cwiseAbs().maxCoeff();
  if (!((m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale) || Eigen::LLT<Eigen::MatrixXd>(m).info() != Eigen::Success) {
    throw_invalid(where, "metric", excerpt(metric), "must be symmetric positive definite");
  }
}

/// A point of the quadric <q, q> = K from 3 finite numbers: on the sphere any nonzero vector,
/// divided by its length; on the hyperbolic plane a vector with z > 0 and <q, q> < 0 (inside the
/// future cone), divided by sqrt(-<q, q>).
template <int K>
Eigen::Vector3d quadric_point(const std::vector<double>& x, const char* name, std::string_view where) {
  require_numbers(where, name, x, 3, "a point x,y,z");
  const Eigen::Vector3d p(x.data());
  if constexpr (K > 0) {
    if (!(p.stableNorm() > 0)) throw_invalid(where, name, excerpt(x), "has zero length");
    return p.stableNormalized();
  } else {
    const double scale = p.cwiseAbs().maxCoeff();  // against overflow of the squares
    const Eigen::Vector3d u = scale > 0 ? Eigen::Vector3d(p / scale) : p;
    const double inner = manifolds::HyperbolicPlane::inner(u, u);
    if (!(u[2] > 0 && inner < 0)) {
      throw_invalid(where, name, excerpt(x),
                    "is not a point of the hyperbolic plane's sheet and cannot be moved onto it (it needs z > 0 and "
                    "z^2 > x^2 + y^2)");
    }
    return u / std::sqrt(-inner);
  }
}

/// A guess of n numbers each (xi0: the Lie-group kernel only).
void check_guess(const Guess& guess, int n, std::string_view group, bool lie_kernel, std::string_view where) {
  const auto size = static_cast<std::size_t>(n);
  const std::string of_group = std::to_string(n) + " for group " + std::string(group);
  if (!guess.v0.empty()) require_numbers(where, "v0", guess.v0, size, "a guess of v(0), " + of_group);
  if (guess.xi0.empty()) return;
  if (!lie_kernel) {
    throw_invalid(where, "xi0", excerpt(guess.xi0),
                  "is a guess of the Lie-group kernel's xi (a Cartan-Schouten connection), not of the general solver's Xi");
  }
  require_numbers(where, "xi0", guess.xi0, size, "a guess of xi(0), " + of_group);
}

}  // namespace

CheckedGroupProblem checked(const GroupProblem& problem, const Guess& guess, bool elements, std::string_view where) {
  using connections::ConnectionKind;
  CheckedGroupProblem out;
  out.model = &models::find_model(problem.group, problem.model, where);
  const models::ModelInfo& model = *out.model;
  const auto n = static_cast<std::size_t>(model.dim);
  out.inertia = problem.inertia.empty() ? model.default_inertia : problem.inertia;
  require_matrix_numbers(where, "inertia", out.inertia, n, model.group);
  models::check_inertia(model, out.inertia, where);
  const auto only = [](ConnectionKind owner) { return "is an option of connection " + std::string(to_string(owner)) + " only"; };
  if (problem.connection != ConnectionKind::LeviCivita && !problem.metric.empty()) {
    throw_invalid(where, "metric", excerpt(problem.metric), only(ConnectionKind::LeviCivita));
  }
  if (problem.connection != ConnectionKind::Coefficients && !problem.alpha.empty()) {
    throw_invalid(where, "alpha", excerpt(problem.alpha), only(ConnectionKind::Coefficients));
  }
  if (problem.connection == ConnectionKind::LeviCivita && !problem.metric.empty()) {
    require_matrix_numbers(where, "metric", problem.metric, n, model.group);
    require_metric(where, problem.metric, model.dim);
  }
  if (problem.connection == ConnectionKind::Coefficients) {
    require_numbers(where, "alpha", problem.alpha, n * n * n, "alpha[i][j][k] in (i, j, k) order");
  }
  out.g0 = problem.g0.empty() ? model.identity : problem.g0;
  const std::string element = std::string(model.element_what);
  require_numbers(where, "g0", out.g0, model.element_size, element);
  if (problem.gT.empty()) throw_invalid(where, "gT", "(missing)", "is required");
  require_numbers(where, "gT", problem.gT, model.element_size, element);
  check_guess(guess, model.dim, model.group, lie_kernel(problem), where);
  if (elements) {
    model.check_element(out.g0, where, "g0");
    model.check_element(problem.gT, where, "gT");
  }
  return out;
}

template <int K>
general::ErasedProblem<manifolds::Quadric<K>> quadric_problem(const ManifoldProblem& problem, const Guess& guess,
                                                              std::string_view where) {
  using Q = manifolds::Quadric<K>;
  require_numbers(where, "mass", problem.mass, 2, "a1,a2");
  for (double a : problem.mass) {
    if (!(a > 0)) throw_invalid(where, "mass", excerpt(problem.mass), "must be positive");
  }
  require_finite(problem.gravity, where, "gravity");
  const Eigen::Vector3d q0 = quadric_point<K>(problem.q0, "q0", where), qT = quadric_point<K>(problem.qT, "qT", where);
  manifolds::Sphere::Frame frame;
  if constexpr (K > 0) {
    if (q0.cross(qT).norm() < 1e-12) {
      throw_invalid(where, "q0/qT", excerpt(problem.q0) + " / " + excerpt(problem.qT),
                    q0.dot(qT) > 0 ? "are equal: the frame's e1 (towards qT along the minimal great circle) is undefined"
                                   : "are antipodal: the minimal great circle is not unique");
    }
    frame.col(0) = (qT - q0.dot(qT) * q0).normalized();  // along the minimal great circle
    frame.col(1) = q0.cross(Eigen::Vector3d(frame.col(0)));
  } else {
    const Eigen::Vector3d towards = Q::project_tangent(q0, qT);  // along the geodesic to qT; <., .> = J
    if (!(std::sqrt(std::max(0.0, Q::inner(towards, towards))) > 1e-12)) {
      throw_invalid(where, "q0/qT", excerpt(problem.q0) + " / " + excerpt(problem.qT),
                    "are equal: the frame's e1 (towards qT along the geodesic) is undefined");
    }
    frame.col(0) = towards / std::sqrt(Q::inner(towards, towards));
    frame.col(1) = Q::metric(q0) * q0.cross(Eigen::Vector3d(frame.col(0)));  // J (q0 x e1): unit, tangent, J-orthogonal to e1
  }
  if (!guess.v0.empty()) require_numbers(where, "v0", guess.v0, 2, "a guess of v(0) in the frame (e1, e2)");
  if (!guess.xi0.empty()) {
    throw_invalid(where, "xi0", excerpt(guess.xi0), "is a guess of the Lie-group kernel's xi, not of the " +
                                                         std::string(Q::name()) + "'s solver");
  }
  using Particle = general::KineticPotential<Q>;
  const Particle particle = Particle::with_linear_potential(Eigen::Vector2d(problem.mass[0], problem.mass[1]).asDiagonal(),
                                                            Eigen::Vector3d(0, 0, problem.gravity));
  return {Q{}, general::ErasedLagrangian<Q>(particle), problem.T, problem.N, q0, qT, frame};
}

template general::ErasedProblem<manifolds::Sphere> quadric_problem<1>(const ManifoldProblem&, const Guess&, std::string_view);
template general::ErasedProblem<manifolds::HyperbolicPlane> quadric_problem<-1>(const ManifoldProblem&, const Guess&,
                                                                                 std::string_view);

}  // namespace cartan::api::detail

namespace cartan::api {

void check(const GroupProblem& problem, const Guess& guess, std::string_view where) {
  (void)detail::checked(problem, guess, false, where);
}

void check(const ManifoldProblem& problem, const Guess& guess, std::string_view where) {
  (void)detail::visit_manifold(problem, guess, where, [](const auto&) { return 0; });
}

ManifoldProblem on_manifold(const ManifoldProblem& problem, const Guess& guess, std::string_view where) {
  ManifoldProblem out = problem;
  detail::visit_manifold(problem, guess, where, [&](const auto& quadric) {
    out.q0.assign(quadric.q0.data(), quadric.q0.data() + 3);
    out.qT.assign(quadric.qT.data(), quadric.qT.data() + 3);
    return 0;
  });
  return out;
}

}  // namespace cartan::api
