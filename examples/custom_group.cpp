// A user-defined Lie group: the affine group of the line Aff(1) = {x -> a x + b, a > 0}, written
// against the LieGroup concept (cartan/groups/group.hpp) with closed forms, then used by the generic
// algorithms: a Cartan–Schouten connection and its parallel transport, and the
// transported-velocity boundary-value problem (eq:reduced-system) for a free particle.
// docs/user-guide.md "Defining a new group" walks through this file. Run by ctest
// (examples/CMakeLists.txt); exits non-zero when one of its checks fails.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "cartan/connections/cartan_schouten.hpp"
#include "cartan/groups/matrix_group.hpp"
#include "cartan/mechanics/euler_poincare.hpp"
#include "cartan/mechanics/natural_system.hpp"
#include "cartan/methods/lie_group/continuation.hpp"
#include "cartan/transport/parallel_transport.hpp"

// Elements are the coordinates (a, b) of the matrix [[a, b], [0, 1]]; the algebra basis is
// E1 = [[1, 0], [0, 0]] (scaling), E2 = [[0, 1], [0, 0]] (translation), with [E1, E2] = E2.
struct AffineLine {
  static constexpr int kDim = 2;
  using Element = Eigen::Vector2d;        // (a, b), a > 0
  using Tangent = Eigen::Vector2d;        // (s, t) = s E1 + t E2
  using MatrixRep = Eigen::Matrix2d;      // [[a, b], [0, 1]] and [[s, t], [0, 0]]
  using AlgebraMatrix = Eigen::Matrix2d;  // linear maps on algebra coordinates

  static constexpr std::string_view name() { return "aff1"; }
  static Element identity() { return {1, 0}; }
  static Element compose(const Element& g, const Element& h) { return {g[0] * h[0], g[0] * h[1] + g[1]}; }
  static Element inverse(const Element& g) { return {1 / g[0], -g[1] / g[0]}; }

  /// exp(s, t) = (e^s, t phi(s)) with phi(s) = (e^s - 1)/s (expm1 keeps it accurate near 0).
  static Element exp(const Tangent& v) { return {std::exp(v[0]), v[1] * phi(v[0])}; }
  static Tangent log(const Element& g) {
    const double s = std::log(g[0]);
    return {s, g[1] / phi(s)};
  }

  static MatrixRep hat(const Tangent& v) { return (MatrixRep() << v[0], v[1], 0, 0).finished(); }
  static Tangent vee(const MatrixRep& x) { return {x(0, 0), x(0, 1)}; }
  static MatrixRep matrix(const Element& g) { return (MatrixRep() << g[0], g[1], 0, 1).finished(); }

  /// g hat(v) g^{-1} = hat(s, a t - b s).
  static AlgebraMatrix Ad(const Element& g) { return (AlgebraMatrix() << 1, 0, -g[1], g[0]).finished(); }
  /// [u, w] = (0, u_s w_t - w_s u_t).
  static AlgebraMatrix ad(const Tangent& u) { return (AlgebraMatrix() << 0, 0, -u[1], u[0]).finished(); }

  // Tangent vectors at g in the coordinates of Element: d/de of (a, b) along g exp(e v) and exp(e v) g.
  static Element left_translate(const Element& g, const Tangent& v) { return {g[0] * v[0], g[0] * v[1]}; }
  static Element right_translate(const Element& g, const Tangent& v) { return {v[0] * g[0], v[0] * g[1] + v[1]}; }
  static Tangent left_trivialise(const Element& g, const Element& x) { return {x[0] / g[0], x[1] / g[0]}; }
  static Tangent right_trivialise(const Element& g, const Element& x) {
    return {x[0] / g[0], x[1] - x[0] * g[1] / g[0]};
  }

  /// Throws std::invalid_argument naming the value unless g is finite with a > 0.
  static void validate(const Element& g, std::string_view name) {
    cartan::require_finite(g, "AffineLine", name);
    if (!(g[0] > 0)) cartan::throw_invalid("AffineLine", name, cartan::format_value(g), "is not in Aff(1): a must be > 0");
  }

 private:
  static double phi(double s) { return s == 0 ? 1.0 : std::expm1(s) / s; }
};

static_assert(cartan::groups::LieGroup<AffineLine>);

// The same group from its basis alone (cartan/groups/matrix_group.hpp): a reference for the closed forms.
struct AffineLineBasis {
  static constexpr int kDim = 2;
  static constexpr int kMatrixSize = 2;
  static constexpr std::string_view name() { return "aff1-generic"; }
  static std::array<Eigen::Matrix2d, 2> basis() {
    return {(Eigen::Matrix2d() << 1, 0, 0, 0).finished(), (Eigen::Matrix2d() << 0, 1, 0, 0).finished()};
  }
};
using AffineLineGeneric = cartan::groups::MatrixLieGroup<AffineLineBasis>;

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("  [%s] %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok) ++failures;
}

double max_abs(const Eigen::MatrixXd& x) { return x.cwiseAbs().maxCoeff(); }

}  // namespace

int main() {
  using namespace cartan;
  using G = AffineLine;
  std::printf("Aff(1): closed forms against the generic matrix group of the same basis\n");
  // Rounding only: the generic path goes through Eigen's matrix exponential and logarithm
  // (~1e-15 relative); 1e-12 leaves room without hiding a wrong formula (those are O(1) off).
  const G::Tangent v(0.7, -1.3), w(-0.4, 0.9);
  const G::Element g = G::exp(v);
  double worst = 0;
  worst = std::max(worst, max_abs(G::matrix(g) - AffineLineGeneric::exp(v)));
  worst = std::max(worst, max_abs(G::log(g) - AffineLineGeneric::log(G::matrix(g))));
  worst = std::max(worst, max_abs(G::Ad(g) - AffineLineGeneric::Ad(G::matrix(g))));
  worst = std::max(worst, max_abs(G::ad(v) - AffineLineGeneric::ad(v)));
  worst = std::max(worst, max_abs(G::matrix(G::compose(g, G::exp(w))) - G::matrix(g) * G::matrix(G::exp(w))));
  worst = std::max(worst, max_abs(G::hat(G::left_trivialise(g, G::left_translate(g, w))) - G::hat(w)));
  std::printf("  max difference over exp, log, Ad, ad, compose, trivialise: %.2e\n", worst);
  check(worst < 1e-12, "closed forms agree with the generic group to 1e-12");

  std::printf("Cartan-Schouten connection, lambda = 1/2 (tor-cur-lie-alg)\n");
  const connections::InvariantConnection<G> conn = connections::cartan_schouten<G>(0.5);
  const G::Tangent torsion = conn.torsion(v, w);
  const G::Tangent curvature = conn.curvature(v, w, v);
  std::printf("  T(v, w) = (%.3g, %.3g), R(v, w) v = (%.6f, %.6f)\n", torsion[0], torsion[1], curvature[0],
              curvature[1]);
  check(max_abs(curvature - connections::cartan_schouten_curvature<G>(0.5, v, w, v)) < 1e-14,
        "curvature = -1/4 [[v, w], v] (closed form, rounding only)");

  // Transport along the one-parameter subgroup t -> exp(t u) (constant body velocity u): the
  // generator -lambda ad_u is constant, so P(0 -> 1) = exp(-lambda ad_u) = Ad(exp(-lambda u))
  // exactly, for every method (cor-parr, parr-tran-Cartan-lambda).
  const double lambda = 0.3;
  const G::Tangent u(0.8, 0.5);
  const G::AlgebraMatrix p = transport::transport_operator(connections::cartan_schouten<G>(lambda), [&](double) { return u; }, 0.0, 1.0, 20,
                                                transport::TransportMethod::Magnus4);
  const double transport_error = max_abs(p - G::Ad(G::exp(G::Tangent(-lambda * u))));
  std::printf("Transport along exp(t u), lambda = %.1f: |P - Ad(exp(-lambda u))| = %.2e\n", lambda, transport_error);
  check(transport_error < 1e-13, "transport equals the closed form Ad(exp(-lambda u))");

  // A free particle with a left-invariant kinetic energy l = 1/2 v.I v on Aff(1), from the
  // identity to gT at T = 2 (the second-order scheme).
  using Free = mechanics::NaturalLagrangian<G, mechanics::ZeroPotential<G>>;
  const Free particle((G::AlgebraMatrix() << 1.0, 0.2, 0.2, 2.0).finished());
  const G::Element gT(2.0, 1.5);
  const double tol = 1e-10;
  std::printf("Transported-velocity BVP, l = 1/2 v.I v, g0 = e, gT = (2, 1.5), T = 2, N = 400, order 2\n");
  transported::ContinuationOptions options;
  options.shooting = {.order = transported::SchemeOrder::Second, .tolerance = tol};
  transported::TransportedSolution<G> classical;
  for (const double lam : {0.0, 0.5, 1.0}) {
    const transported::TransportedProblem<G, Free> problem{particle, lam, 2.0, 400, G::identity(), gT};
    const transported::TransportedSolution<G> s = transported::solve_continuation_in_T(problem, options);
    std::printf("  lambda = %.1f: %s, v0 = (%.6f, %.6f), terminal error %.2e, %d sweeps (%s)\n", lam,
                std::string(to_string(s.status)).c_str(), s.v0[0], s.v0[1], s.terminal_error, s.sweeps, s.branch.c_str());
    check(s.converged() && s.terminal_error <= tol, "lambda = " + std::to_string(lam).substr(0, 3) + " converged");
    if (lam == 0.0) classical = s;
  }

  // At lambda = 0 the transport is trivial (v is the body velocity) and eq:reduced-system is
  // eq:EP-left: integrating the classical equations from v0 must land on gT. RKMK4 with 4000
  // steps is exact to ~1e-12 here, so the gap is the order-2 scheme's O(h^2) error: with
  // h = 0.005 and O(1) derivatives ~1e-5 (measured 1.1e-6); 1e-4 flags an O(h) or wrong solution.
  const mechanics::Trajectory<G> ep = mechanics::euler_poincare<G>(groups::Side::Left, particle, G::identity(), classical.v0, 2.0, 4000);
  const double gap = groups::log_between<G>(gT, ep.g.back()).norm();
  std::printf("Euler-Poincare from the lambda = 0 v0 ends |log(gT^-1 g(T))| = %.2e from gT\n", gap);
  check(gap < 1e-4, "lambda = 0 solution is the classical Euler-Poincare motion (to the scheme's O(h^2))");

  std::printf("%s\n", failures == 0 ? "all checks passed" : "SOME CHECKS FAILED");
  return failures == 0 ? 0 : 1;
}
