#include "problems.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <cmath>
#include <type_traits>

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
                      " (the matrix, row-major) for " + std::string(group));
  }
  require_numbers(where, name, x, x.size(), "");
}

using models::square_matrix;

/// A metric or a mass, given as n or n^2 finite numbers (require_matrix_numbers): symmetric (to
/// 1e-12 of its largest entry) and positive definite.
void require_spd(std::string_view where, const char* name, const std::vector<double>& numbers, Eigen::Index n) {
  const Eigen::MatrixXd m = square_matrix(numbers, n);
  const double scale = m.cwiseAbs().maxCoeff();
  if (!((m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale) || Eigen::LLT<Eigen::MatrixXd>(m).info() != Eigen::Success) {
    throw_invalid(where, name, excerpt(numbers), "must be symmetric positive definite");
  }
}

/// The connection data given with `connection` on a space of dimension n: a metric with
/// levi-civita only (and only where `metric_allowed`: a group's), alpha with coefficients only
/// (n^3 numbers).
void require_connection_data(connections::ConnectionKind connection, const std::vector<double>& metric,
                             const std::vector<double>& alpha, std::size_t n, std::string_view space, bool metric_allowed,
                             std::string_view where) {
  using connections::ConnectionKind;
  const auto only = [](ConnectionKind owner) { return "is an option of connection " + std::string(to_string(owner)) + " only"; };
  if (connection != ConnectionKind::LeviCivita && !metric.empty()) throw_invalid(where, "metric", excerpt(metric), only(ConnectionKind::LeviCivita));
  if (connection != ConnectionKind::Coefficients && !alpha.empty()) throw_invalid(where, "alpha", excerpt(alpha), only(ConnectionKind::Coefficients));
  if (!metric.empty()) {
    if (!metric_allowed) {
      throw_invalid(where, "metric", excerpt(metric),
                    "is not an option of " + std::string(space) + " (its Levi-Civita connection is that of its own metric)");
    }
    require_matrix_numbers(where, "metric", metric, n, space);
    require_spd(where, "metric", metric, static_cast<Eigen::Index>(n));
  }
  if (connection == ConnectionKind::Coefficients) {
    require_numbers(where, "alpha", alpha, n * n * n, "alpha[i][j][k] in (i, j, k) order");
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
  if (!guess.Xi0.empty()) {
    if (lie_kernel) {
      throw_invalid(where, "Xi0", excerpt(guess.Xi0),
                    "is a guess of the general solver's Xi, not of the Lie-group kernel's xi (a Cartan-Schouten connection)");
    }
    require_numbers(where, "Xi0", guess.Xi0, size * size, "a guess of Xi(0), row-major");
  }
  if (guess.xi0.empty()) return;
  if (!lie_kernel) {
    throw_invalid(where, "xi0", excerpt(guess.xi0),
                  "is a guess of the Lie-group kernel's xi (a Cartan-Schouten connection), not of the general solver's Xi");
  }
  require_numbers(where, "xi0", guess.xi0, size, "a guess of xi(0), " + of_group);
}

}  // namespace

CheckedGroupProblem checked(const GroupProblem& problem, const Guess& guess, bool elements, std::string_view where) {
  CheckedGroupProblem out;
  out.model = &models::find_model(problem.group, problem.model, where);
  const models::ModelInfo& model = *out.model;
  const auto n = static_cast<std::size_t>(model.dim);
  out.inertia = problem.inertia.empty() ? model.default_inertia : problem.inertia;
  require_matrix_numbers(where, "inertia", out.inertia, n, "group " + std::string(model.group));
  models::check_inertia(model, out.inertia, where);
  require_connection_data(problem.connection, problem.metric, problem.alpha, n, "group " + std::string(model.group), true,
                          where);
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

namespace {

using manifolds::ComponentMatrixOf;
using manifolds::FrameOf;
using manifolds::PointOf;

constexpr std::string_view kParticle = "particle";

/// The connection of a manifold problem: the space's default when none is named.
connections::ConnectionKind connection_of(const ManifoldProblem& p, const SpaceInfo& space) {
  return p.connection.value_or(space.connections.front());
}

/// The manifold M of a checked problem with its connection.
template <class M>
M make_manifold(const ManifoldProblem& p, connections::ConnectionKind connection, const Eigen::MatrixXd& mass) {
  using connections::ConnectionKind;
  if constexpr (requires { typename M::Group; }) {
    switch (connection) {
      case ConnectionKind::CartanSchouten: return M::cartan_schouten(p.lambda);
      case ConnectionKind::LeviCivita:
        return M::levi_civita(p.metric.empty() ? ComponentMatrixOf<M>(mass) : ComponentMatrixOf<M>(square_matrix(p.metric, M::kDim)));
      case ConnectionKind::Coefficients: return M::coefficients(p.alpha);
    }
    throw std::logic_error("make_manifold: unknown connection");
  } else if constexpr (requires { typename M::Coefficients; }) {  // Euclidean<n>
    typename M::Coefficients gamma;  // gamma[i](k, j) = Gamma^k_ij = alpha[i][j][k]
    constexpr int n = M::kDim;
    for (int i = 0; i < n; ++i) {
      gamma[static_cast<std::size_t>(i)].setZero();
      if (connection != ConnectionKind::Coefficients) continue;
      for (int j = 0; j < n; ++j) {
        for (int k = 0; k < n; ++k) gamma[static_cast<std::size_t>(i)](k, j) = p.alpha[static_cast<std::size_t>((i * n + j) * n + k)];
      }
    }
    return M(gamma);
  } else {
    return M{};
  }
}

/// A point of the problem's space from its numbers (`name`: q0 or qT): a quadric's moved onto it,
/// a group element's checked and projected (models/catalogue.hpp), R^n's coordinates.
template <class M>
PointOf<M> point_of(const std::vector<double>& x, const char* name, const SpaceInfo& space, std::string_view where) {
  if constexpr (requires { typename M::Group; }) {
    const models::ModelInfo& info = models::find_model(space.name, {}, where);
    require_numbers(where, name, x, info.element_size, std::string(info.element_what));
    info.check_element(x, where, name);
    return models::element_of<typename M::Group>(x);
  } else if constexpr (requires { typename M::Coefficients; }) {
    require_numbers(where, name, x, M::kDim, std::to_string(M::kDim) + " coordinates");
    return Eigen::Map<const PointOf<M>>(x.data());
  } else {
    return quadric_point<std::is_same_v<M, manifolds::Sphere> ? 1 : -1>(x, name, where);
  }
}

/// "GeneralProblem: <name> = ..." (the general problem's validation) as "<where>: <name> = ...".
template <class Problem>
void validate_for(const Problem& problem, std::string_view where) {
  try {
    problem.validate();
  } catch (const std::invalid_argument& e) {
    constexpr std::string_view prefix = "GeneralProblem: ";
    const std::string_view message = e.what();
    throw std::invalid_argument(std::string(where) + ": " +
                                std::string(message.starts_with(prefix) ? message.substr(prefix.size()) : message));
  }
}

}  // namespace

template <class M>
general::ErasedProblem<M> manifold_problem(const ManifoldProblem& p, const Guess& guess, std::string_view where) {
  constexpr int m = M::kDim;
  constexpr int d = manifolds::VectorOf<M>::RowsAtCompileTime;
  const SpaceInfo& space = find_space(p.manifold, where);
  if (p.model != kParticle) {
    throw_invalid(where, "model", quote_input(p.model),
                  "is not a model of " + std::string(space.name) + " (models: particle; a Lagrangian defined in Python is "
                  "solved and verified in Python)");
  }
  const connections::ConnectionKind connection = connection_of(p, space);
  require_connection(space, connection, where);
  require_connection_data(connection, p.metric, p.alpha, m, space.name, space.kind == SpaceKind::Group, where);
  Eigen::MatrixXd mass = Eigen::MatrixXd::Identity(m, m);
  if (!p.mass.empty()) {
    require_matrix_numbers(where, "mass", p.mass, m, space.name);
    require_spd(where, "mass", p.mass, m);
    mass = square_matrix(p.mass, m);
  }
  require_finite(p.gravity, where, "gravity");
  if (p.gravity != 0 && !space.gravity) {
    throw_invalid(where, "gravity", format_value(p.gravity),
                  "does not apply on " + std::string(space.name) + " (V = G q[last] needs points that are vectors)");
  }
  const M manifold = make_manifold<M>(p, connection, mass);
  PointOf<M> q0;
  if constexpr (requires { typename M::Group; }) {
    q0 = p.q0.empty() ? PointOf<M>(M::Group::identity()) : point_of<M>(p.q0, "q0", space, where);
  } else {
    q0 = point_of<M>(p.q0, "q0", space, where);
  }
  const PointOf<M> qT = point_of<M>(p.qT, "qT", space, where);
  std::optional<FrameOf<M>> frame0;
  if (!p.frame0.empty()) {
    require_numbers(where, "frame0", p.frame0, static_cast<std::size_t>(m * d),
                    std::to_string(m) + " rows of " + std::to_string(d) + " numbers: e_1 .. e_" + std::to_string(m) + " at q0");
    frame0 = Eigen::Map<const Eigen::Matrix<double, m, d, m == 1 ? Eigen::ColMajor : Eigen::RowMajor>>(p.frame0.data()).transpose();
  }  // without it, validate_for refuses the fallback frame where A is not a multiple of I
  if (!guess.v0.empty()) require_numbers(where, "v0", guess.v0, m, "a guess of v(0) in the frame at q0");
  if (!guess.Xi0.empty()) require_numbers(where, "Xi0", guess.Xi0, m * m, "a guess of Xi(0), row-major");
  if (!guess.xi0.empty()) {
    throw_invalid(where, "xi0", excerpt(guess.xi0),
                  "is a guess of a group model's xi (a problem on a group), not of a manifold problem's (give v0)");
  }
  const ComponentMatrixOf<M> A = mass;
  const auto particle = [&] {  // V = G q[last] where points are vectors and G != 0, else none
    if constexpr (!requires { typename M::Group; }) {
      if (p.gravity != 0) {
        PointOf<M> c = PointOf<M>::Zero();
        c[c.size() - 1] = p.gravity;
        return general::erased_particle_in_linear_potential<M>(A, c);
      }
    }
    return general::erased_particle<M>(A);
  };
  general::ErasedProblem<M> out{manifold, particle(), p.T, p.N, q0, qT, frame0};
  validate_for(out, where);
  return out;
}

#define CARTAN_API_MANIFOLD_PROBLEM(M) \
  template general::ErasedProblem<M> manifold_problem<M>(const ManifoldProblem&, const Guess&, std::string_view);
CARTAN_API_MANIFOLD_PROBLEM(manifolds::Sphere)
CARTAN_API_MANIFOLD_PROBLEM(manifolds::HyperbolicPlane)
CARTAN_API_MANIFOLD_PROBLEM(manifolds::Euclidean<2>)
CARTAN_API_MANIFOLD_PROBLEM(manifolds::Euclidean<3>)
CARTAN_API_MANIFOLD_PROBLEM(manifolds::GroupManifold<groups::SO3>)
CARTAN_API_MANIFOLD_PROBLEM(manifolds::GroupManifold<groups::Heisenberg>)
CARTAN_API_MANIFOLD_PROBLEM(manifolds::GroupManifold<groups::SE2>)
CARTAN_API_MANIFOLD_PROBLEM(manifolds::GroupManifold<groups::SE3>)
#undef CARTAN_API_MANIFOLD_PROBLEM

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
  detail::visit_manifold(problem, guess, where, [&]<class M>(const general::ErasedProblem<M>& posed) {
    out.q0 = models::element_numbers(posed.q0);
    out.qT = models::element_numbers(posed.qT);
    out.connection = detail::connection_of(problem, find_space(problem.manifold, where));
    if (out.mass.empty()) out.mass.assign(static_cast<std::size_t>(M::kDim), 1.0);
    out.frame0 = models::element_numbers(posed.initial_frame().transpose());  // the rows e_1 .. e_m
    return 0;
  });
  return out;
}

}  // namespace cartan::api
