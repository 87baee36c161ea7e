#pragma once
// The transported-velocity boundary-value problem (eq:reduced-system) and its solvers
// (transported/): one table of methods, instantiated for every model of every group. Adding a
// method (e.g. the collocation solver of include/cartan/bvp/) is one more row in method_table.
//
//   two-level            the paper's scheme (§7): inner LM shooting on v0, outer fixed point on xi
//   shooting             as `cartan solve`: augmented shooting on (v0, xi0), continued in T when
//                        it does not converge quickly from the geodesic guess
//   single-shooting      augmented shooting from the guess only (no continuation)
//   multiple-shooting    lifted LM over segments of the same scheme
//   continuation-lambda  augmented shooting continued in lambda from lambda_start
//   collocation          fourth-order adaptive collocation of the continuous BVP (bvp/), for the
//                        built-in natural Lagrangians (H3: the closed-form system; other groups:
//                        the generic one), output at the final mesh or `samples` uniform times
// Options have the CLI's names and defaults (apps/cartan): order, tol, max_iterations, samples.

#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <pybind11/stl.h>

#include "bind_models.hpp"
#include "cartan/bvp/transported_solution.hpp"
#include "cartan/transported/continuation.hpp"
#include "cartan/transported/multiple_shooting.hpp"
#include "cartan/transported/two_level.hpp"

namespace cartan::python {

/// The solver options, as given in Python (validated by `check_request`).
struct SolveRequest {
  std::string method = "shooting";
  int order = 1;
  double tol = 1e-10;
  int max_iterations = 200;
  std::optional<int> segments;        ///< multiple-shooting only
  std::optional<double> lambda_start;  ///< continuation-lambda only
  bool has_v0 = false, has_xi0 = false;
  std::optional<int> samples;          ///< collocation only (0: the final mesh)
  std::optional<int> max_nodes;        ///< collocation only

  SchemeOrder scheme_order() const { return order == 2 ? SchemeOrder::Second : SchemeOrder::First; }
  ShootingOptions shooting() const { return {.order = scheme_order(), .tolerance = tol, .max_iterations = max_iterations}; }
};

template <LieGroup G>
struct Guess {
  std::optional<TangentOf<G>> v0;
  std::optional<CovectorOf<G>> xi0;
};

/// Which optional inputs a method accepts.
enum Accepts : unsigned { kNone = 0, kV0 = 1, kXi0 = 2, kSegments = 4, kLambdaStart = 8, kSamples = 16, kMaxNodes = 32 };

/// The potential V of a NaturalLagrangian<G, V> (void for any other Lagrangian).
template <class L>
struct NaturalPotentialOf {
  using type = void;
};
template <LieGroup G, Potential<G> V>
struct NaturalPotentialOf<NaturalLagrangian<G, V>> {
  using type = V;
};

/// The transported BVP by collocation: on H3 the closed-form system (as the CLI), on other
/// groups the generic one; both need mu = I v with a constant inertia (natural Lagrangians).
template <LieGroup G, ReducedLagrangian<G> L>
TransportedSolution<G> solve_by_collocation(const TransportedProblem<G, L>& p, const SolveRequest& r) {
  const bvp::CollocationOptions options{.tol = r.tol, .max_nodes = r.max_nodes.value_or(bvp::kTransportedMaxNodes),
                                        .max_newton_iterations = r.max_iterations};
  using V = typename NaturalPotentialOf<L>::type;
  if constexpr (std::is_void_v<V>) {
    throw_invalid("cartan.solve", "method", "\"collocation\"",
                  "needs a built-in natural Lagrangian (RigidBody, SO3Oscillator, H3Oscillator), "
                  "not one written in Python (its Legendre map may depend on g)");
  } else if constexpr (std::is_same_v<G, Heisenberg>) {
    return bvp::solve_heisenberg_transported(p, options, r.samples.value_or(0));
  } else {
    return bvp::solve_transported_by_collocation(p, options, r.samples.value_or(0),
                                                 bvp::CollocationFallback::ContinuationInT);
  }
}

template <LieGroup G, ReducedLagrangian<G> L>
struct Method {
  const char* name;
  unsigned accepts;
  TransportedSolution<G> (*run)(const TransportedProblem<G, L>&, const SolveRequest&, const Guess<G>&);
};

template <LieGroup G, ReducedLagrangian<G> L>
TangentOf<G> v0_or_geodesic(const TransportedProblem<G, L>& p, const Guess<G>& guess) {
  return guess.v0.value_or(geodesic_guess(p));
}

inline const char* guess_branch(bool given) {
  return given ? "from the given guess" : "direct from the geodesic guess";
}

template <LieGroup G, ReducedLagrangian<G> L>
const std::array<Method<G, L>, 6>& method_table() {
  using P = TransportedProblem<G, L>;
  static const std::array<Method<G, L>, 6> table{{
      {"two-level", kV0, [](const P& p, const SolveRequest& r, const Guess<G>& guess) {
         auto s = solve_two_level(p, {.order = r.scheme_order(), .tolerance = r.tol, .max_outer = r.max_iterations,
                                      .max_inner = r.max_iterations}, v0_or_geodesic(p, guess));
         s.branch = guess_branch(guess.v0.has_value());
         return s;
       }},
      {"shooting", kNone, [](const P& p, const SolveRequest& r, const Guess<G>&) {
         auto s = solve_continuation_in_T(p, {.shooting = r.shooting()});
         s.method = "shooting";
         return s;
       }},
      {"single-shooting", kV0 | kXi0, [](const P& p, const SolveRequest& r, const Guess<G>& guess) {
         auto s = solve_shooting(p, r.shooting(), v0_or_geodesic(p, guess), guess.xi0.value_or(CovectorOf<G>::Zero()));
         s.branch = guess_branch(guess.v0 || guess.xi0);
         return s;
       }},
      {"multiple-shooting", kV0 | kXi0 | kSegments, [](const P& p, const SolveRequest& r, const Guess<G>& guess) {
         return solve_multiple_shooting(p, {.order = r.scheme_order(), .segments = r.segments, .tolerance = r.tol,
                                            .max_iterations = r.max_iterations},
                                        v0_or_geodesic(p, guess), guess.xi0.value_or(CovectorOf<G>::Zero()));
       }},
      {"continuation-lambda", kLambdaStart, [](const P& p, const SolveRequest& r, const Guess<G>&) {
         return solve_continuation_in_lambda(p, r.lambda_start.value_or(0.0), {.shooting = r.shooting()});
       }},
      {"collocation", kSamples | kMaxNodes, [](const P& p, const SolveRequest& r, const Guess<G>&) {
         return solve_by_collocation(p, r);
       }},
  }};
  return table;
}

template <LieGroup G, ReducedLagrangian<G> L>
std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const auto& row : method_table<G, L>()) names.emplace_back(row.name);
  return names;
}

/// Throws std::invalid_argument naming the option ("cartan.solve: method = "x" is not one of:
/// ...", an option the method does not take, order not 1 or 2); tolerances and limits are
/// checked by the solvers themselves.
void check_request(const SolveRequest& request, const std::vector<std::string>& names, unsigned accepts);

template <LieGroup G, ReducedLagrangian<G> L>
const Method<G, L>& find_method(const SolveRequest& request) {
  const auto& table = method_table<G, L>();
  for (const auto& row : table) {
    if (request.method == row.name) {
      check_request(request, method_names<G, L>(), row.accepts);
      return row;
    }
  }
  check_request(request, method_names<G, L>(), kNone);  // throws: not a method name
  return table.front();
}

/// The solution as a dict of the fields of SolveResult (python/cartan/__init__.py).
template <LieGroup G>
py::dict solution_dict(const TransportedSolution<G>& s, const std::string& group, double lambda, double T, int N) {
  py::dict d;
  d["status"] = s.status;
  d["message"] = s.message;
  d["success"] = s.converged;
  d["method"] = s.method;
  d["order"] = s.order;
  d["branch"] = s.branch;
  d["group"] = group;
  d["lam"] = lambda;
  d["T"] = T;
  d["N"] = N;
  const auto& tr = s.trajectory;
  d["t"] = to_numpy(tr.t);
  d["g"] = to_numpy(tr.g);
  d["v"] = to_numpy(tr.v);
  d["mu"] = to_numpy(tr.mu);
  d["xi"] = to_numpy(tr.xi);
  d["v0"] = to_numpy(s.v0);
  d["xi0"] = to_numpy(s.xi0);
  d["terminal_error"] = s.terminal_error;
  d["xi_terminal"] = s.xi_terminal;
  d["outer_iterations"] = s.outer_iterations;
  d["inner_iterations"] = s.inner_iterations;
  d["sweeps"] = s.sweeps;
  d["residual_history"] = to_numpy(s.residual_history);
  d["solve_time"] = s.solve_time_s;
  return d;
}

/// `<Group>._solve(lagrangian, lam, T, N, g0, gT, ...)` for the listed built-in models and any
/// Python-defined Lagrangian on G.
template <LieGroup G, class... Models>
void bind_solvers(GroupClass<G>& group, const std::string& name, Types<Models...>) {
  const Args<G> a{name};
  group.attr("methods") = method_names<G, PythonLagrangian<G>>();
  group.def_static("_solve", [a](const py::object& model, double lambda, double T, int N, const py::object& g0,
                                 const py::object& gT, const std::string& method, int order, double tol,
                                 int max_iterations, std::optional<int> segments, std::optional<double> lambda_start,
                                 const py::object& v0, const py::object& xi0, std::optional<int> samples,
                                 std::optional<int> max_nodes) {
    const SolveRequest request{method,   order,        tol,           max_iterations, segments,
                               lambda_start, !v0.is_none(), !xi0.is_none(), samples,   max_nodes};
    Guess<G> guess;
    if (request.has_v0) guess.v0 = a.tangent(v0, "solve", "v0");
    if (request.has_xi0) guess.xi0 = a.tangent(xi0, "solve", "xi0");
    const ElementOf<G> start = g0.is_none() ? G::identity() : a.element(g0, "solve", "g0");
    const ElementOf<G> end = a.element(gT, "solve", "gT");
    const TransportedSolution<G> s = visit_model<PythonLagrangian<G>, Models...>(model, [&](const auto& l) {
      using L = std::decay_t<decltype(l)>;
      const TransportedProblem<G, L> problem{l, lambda, T, N, start, end};
      return find_method<G, L>(request).run(problem, request, guess);
    });
    return solution_dict(s, a.group, lambda, T, N);
  }, py::arg("lagrangian"), py::arg("lam"), py::arg("T"), py::arg("N"), py::arg("g0"), py::arg("gT"),
     py::arg("method"), py::arg("order"), py::arg("tol"), py::arg("max_iterations"), py::arg("segments"),
     py::arg("lambda_start"), py::arg("v0"), py::arg("xi0"), py::arg("samples"), py::arg("max_nodes"));
}

}  // namespace cartan::python
