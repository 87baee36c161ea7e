#pragma once
// The library's entry point for a problem described by names and numbers (DESIGN.md, layer
// "api"): a built-in model of the catalogue (models/catalogue.hpp) on its group with a
// left-invariant connection, or a particle on the sphere or the hyperbolic plane. The library
// decides what runs:
//   - a Cartan–Schouten connection: the Lie-group kernel, the model's own compiled solve
//     (kernels/lie_group/compiled.hpp: xi in g*, the paper's eq:reduced-system);
//   - Levi-Civita of a left-invariant metric, or any bilinear map alpha: the general solve on
//     GroupManifold<G> (kernels/manifold/compiled.hpp: the frame and Xi of eq:int-diff-EL);
//   - the sphere, the hyperbolic plane: the general solve on the quadric with its Levi-Civita
//     connection;
// and returns one Result in numbers and words, whichever ran. The CLI translates its flags and
// files to these types and the Result to JSON; it names no solver, group type or model type.
// Compiled once in the library target cartan::api (src/api/); this header declares only.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/api/table.hpp"
#include "cartan/connections/connection_kind.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/result.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/status.hpp"
#include "cartan/verify/verdict.hpp"

namespace cartan::api {

/// A built-in model (models/catalogue.hpp) on its group with a left-invariant connection.
struct GroupProblem {
  std::string group = "so3";        ///< a group of the catalogue
  std::string model;                ///< a model of the group; empty: the group's first
  std::vector<double> inertia;      ///< n numbers (the diagonal) or n^2 (row-major); empty: the model's default
  connections::ConnectionKind connection = connections::ConnectionKind::CartanSchouten;
  double lambda = 0.5;              ///< cartan-schouten: the parameter of CS-conn
  std::vector<double> metric;       ///< levi-civita: n or n^2 numbers; empty: the inertia
  std::vector<double> alpha;        ///< coefficients: alpha(e_i, e_j) = sum_k alpha[i][j][k] e_k, n^3 numbers in (i, j, k) order
  double T = 1;
  int N = 100;
  std::vector<double> g0, gT;       ///< the elements' numbers (ModelInfo::element_what); g0 empty: the identity
};

/// The particle l = 1/2 v^T A v - V(q) on any space of the catalogue (spaces.hpp) with one of its
/// connections: a group with a left-invariant connection (Cartan–Schouten of lambda, Levi-Civita of
/// a metric, the bilinear map alpha), the sphere or the hyperbolic plane with Levi-Civita
/// (manifolds/quadric.hpp), R^2 or R^3 flat or with constant Christoffel symbols alpha. v is in
/// the frame transported from frame0 (eq:int-diff-EL); A is in that frame. V = G q[last] (the
/// uniform gravity of the spaces whose points are vectors), 0 on a group. The default frame of the
/// quadrics has e1 the unit tangent at q0 along the minimal geodesic towards qT and e2 = J (q0 x
/// e1), J = diag(1, 1, K) the metric (so q0 and qT may then not be equal, nor antipodal on the
/// sphere); of the other spaces, the space's tangent_basis (the left-invariant basis on a group,
/// the coordinate basis of R^n).
struct ManifoldProblem {
  std::string manifold = "sphere";  ///< a space of spaces()
  std::vector<double> mass;         ///< A: m numbers (the diagonal) or m^2 (row-major), symmetric positive definite; empty: I
  double gravity = 0;               ///< G (spaces with SpaceInfo::gravity)
  /// The points: a quadric's 3 numbers, moved onto it (divided by their length on the sphere, by
  /// sqrt(z^2 - x^2 - y^2) on the hyperbolic plane: z > 0 and z^2 > x^2 + y^2); R^n's n
  /// coordinates; a group element's numbers (models/catalogue.hpp). q0 of a group: empty, the identity.
  std::vector<double> q0, qT;
  double T = 1;
  int N = 100;
  std::optional<connections::ConnectionKind> connection;  ///< empty: the space's first (spaces.hpp)
  double lambda = 0.5;              ///< cartan-schouten (groups)
  std::vector<double> metric;       ///< levi-civita on a group: m or m^2 numbers; empty: the mass
  std::vector<double> alpha;        ///< coefficients: m^3 numbers, alpha(e_i, e_j) = sum_k alpha[i][j][k] e_k in (i, j, k) order
  std::vector<double> frame0;       ///< the rows e_1 .. e_m of the frame at q0 (m x d numbers); empty: the default
  /// "particle" (l above); a result file may name a Lagrangian defined in Python
  /// ("python:<type name>"), which is read but never solved or verified here.
  std::string model = "particle";
};

/// A trajectory as numbers, one row per time t_k.
struct Samples {
  Eigen::VectorXd t;
  Table points;  ///< a group element's numbers (models::element_numbers) or the point on the manifold
  /// Where the general kernel ran: its frame at each sample, the d x m matrix whose columns are
  /// e_1 .. e_m, row-major (d m numbers a row); empty where the Lie-group kernel ran.
  Table frames;
  Table v, mu;   ///< n numbers each
  /// The auxiliary variable: xi in g* (n numbers) where the Lie-group kernel ran, else the
  /// general Xi (n^2 numbers, row-major).
  Table aux;
};

/// Guesses of v(0), n numbers, and of the auxiliary at 0: xi0, n numbers, where the Lie-group
/// kernel runs, Xi0, n^2 numbers row-major, where the general kernel does; or a whole trajectory
/// (an earlier solution's samples, with the kernel's auxiliary; mu need not be given): the start
/// of collocation, and its first sample the others' guess. Empty: none.
struct Guess {
  std::vector<double> v0, xi0, Xi0;
  std::optional<Samples> trajectory;
};

/// What a solution carries along its samples (kernels/lie_group/along.hpp, kernels/manifold/along.hpp),
/// one row per time: the frames (on a group the transport P_k, n x n; on a manifold the frame,
/// d x m; row-major), the body velocity u, and for a Lagrangian the energy E_k and the cumulative
/// discrete action (0 at the first sample; its last entry is the action).
struct Along {
  Table frames, u;
  Eigen::VectorXd energy, cumulative_action;
};

/// What every solve returns, whichever kernel ran: the kernels' ResultCore (principle/result.hpp;
/// its action is the Lie-group kernel's discrete action S_h, or where the general kernel ran the
/// action along the samples, kernels/manifold/along.hpp, as Python's result has it; NaN for a
/// result stopped on request) and the solution as numbers.
struct Result : ResultCore {
  bool lie_kernel = false;   ///< the auxiliary is xi (n numbers a row); else Xi (n^2)
  Samples samples;           ///< the solution; at a failure the best iterate of the requested problem, or no rows
  std::optional<Eigen::MatrixXd> frame0;  ///< a manifold problem: the rows e1, e2 of its frame at q0
  Eigen::VectorXd v0, aux0;  ///< the unknowns solved for: v(0) and the auxiliary at 0 (xi0, or Xi0 row-major)
  /// What the solution carries along it, where it was asked for (erased.hpp, SolveOutputs): none
  /// for a result stopped on request (the derived quantities would cost what the stop saved).
  std::optional<Along> along;
};

/// Whether the Lie-group kernel (xi in g*) solves `problem`: a Cartan–Schouten connection.
inline bool lie_kernel(const GroupProblem& problem) {
  return problem.connection == connections::ConnectionKind::CartanSchouten;
}

/// Throws std::invalid_argument "<where>: <name> = <value> <problem>" for what a problem and its
/// guess tell wrong by themselves: unknown names, wrong sizes, non-finite numbers, an inertia the
/// model refuses, a metric that is not symmetric positive definite, connection data of another
/// connection, a guess of xi for the general solver; on a manifold, an unknown manifold or a
/// connection it does not take, a mass that is not symmetric positive definite, gravity where
/// it does not apply, points that cannot be moved onto it or are not elements of the group, a
/// frame0 of the wrong size or not a basis of the tangent space at q0, and (with the quadrics'
/// default frame) q0, qT equal or antipodal on the sphere. Not that g0 and gT are elements of the
/// group: solve checks that (so that a sweep reports such a point as its own row), nor the options.
void check(const GroupProblem& problem, const Guess& guess = {}, std::string_view where = "cartan::api::check");
void check(const ManifoldProblem& problem, const Guess& guess = {}, std::string_view where = "cartan::api::check");

/// check(problem, guess), then the problem as solve poses it: q0 and qT moved onto the manifold
/// (a group's q0 the identity when none was given), the connection named, the mass and the
/// frame0 it solved with: what a caller echoes (what a result file records).
ManifoldProblem on_manifold(const ManifoldProblem& problem, const Guess& guess = {},
                            std::string_view where = "cartan::api::on_manifold");

/// Solves `problem` as `options` say. Throws std::invalid_argument "<where>: <name> = <value>
/// <problem>" for what check() refuses, boundary data that are not elements of the group, and
/// whatever the solver's validation refuses (options, T, N); numerical failure is a status.
Result solve(const GroupProblem& problem, const SolveOptions& options = {}, const Guess& guess = {},
             std::string_view where = "cartan::api::solve");
Result solve(const ManifoldProblem& problem, const SolveOptions& options = {}, const Guess& guess = {},
             std::string_view where = "cartan::api::solve");

/// Every check of verify/ on `samples` as a solution of `problem` by a method of the given order
/// to `tol` (the Lie-group kernel's checks for a Cartan–Schouten connection, the general ones
/// otherwise); a `status` other than converged adds a failing `converged` check. The samples' points
/// are read as they are (not projected onto the group): the checks see the data.
verify::Report verify(const GroupProblem& problem, const Samples& samples, int order, double tol,
                      Status status = Status::Converged, std::string_view where = "cartan::api::verify");
verify::Report verify(const ManifoldProblem& problem, const Samples& samples, int order, double tol,
                      Status status = Status::Converged, std::string_view where = "cartan::api::verify");

}  // namespace cartan::api
