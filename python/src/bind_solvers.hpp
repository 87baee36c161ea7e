#pragma once
// `<Group>._solve(...)`: the library's solve through the api's door for problems given as objects
// (api/erased.hpp) for the listed built-in models (each its own compiled solve) and any Lagrangian
// written in Python (behind the erased Lagrangian), with the CLI's method names and options
// (SolveOptions). Nothing is decided here: the options are translated, the library runs, and its
// result becomes a dict of SolveResult's fields (python/cartan/__init__.py).
//
// Ctrl-C: the monitor's stop request takes the GIL and runs PyErr_CheckSignals, so a long solve
// of a built-in model (which runs without the GIL) raises KeyboardInterrupt within one iteration.
// A `progress` callable receives (stage, iteration, residual) once per iteration.
// `<Group>._verify(...)`: the library's checks and verdict (api::verify) on a result of any model,
// as a dict of VerifyReport's fields. `<Group>._along(...)`: the transport P_k, body velocity u_k,
// energy and cumulative action along a result (api::along), for a loaded file; `_solve` returns
// them with the solution.

#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bind_models.hpp"
#include "report_dict.hpp"
#include "cartan/api/erased.hpp"

namespace cartan::python {

/// A Lagrangian written in Python as the solvers take it: the erased Lagrangian (`Solved`), whose
/// solve and verify are compiled in the library, keeping the adapter's callback state.
template <groups::LieGroup G>
class ErasedPythonLagrangian : public mechanics::ErasedLagrangian<G> {
 public:
  using Solved = mechanics::ErasedLagrangian<G>;
  explicit ErasedPythonLagrangian(const py::object& object) : ErasedPythonLagrangian(PythonLagrangian<G>(object)) {}
  const CallbackState& state() const { return python_.state(); }

 private:
  explicit ErasedPythonLagrangian(const PythonLagrangian<G>& python) : Solved(python), python_(python) {}
  PythonLagrangian<G> python_;
};

/// The type a model is solved as: a built-in model as itself, a Python one as its `Solved` type.
template <class L>
struct SolvedAs {
  using type = L;
};
template <class L>
  requires requires { typename L::Solved; }
struct SolvedAs<L> {
  using type = typename L::Solved;
};
template <class L>
using SolvedAsT = typename SolvedAs<std::decay_t<L>>::type;

/// cartan.solve's options: the library's words (principle/options.hpp), whose defaults stand
/// for every keyword Python leaves at None.
using SolveRequest = OptionWords;

/// The samples (api::Samples, rows of numbers) of any object with t, g, v, xi (and mu when
/// `with_mu`; zeros without it) as attributes or keys, e.g. a SolveResult: a guess for `solve`
/// (mu is then not needed) or the data of `verify`, `along` and `sol`.
template <groups::LieGroup G>
api::Samples samples_of(const py::object& source, const Args<G>& a, const std::string& where, const char* argument, bool with_mu) {
  const auto field = [&](const char* name) -> py::object {
    if (py::hasattr(source, name)) return source.attr(name);
    if (py::isinstance<py::dict>(source) && source.contains(name)) return source[py::str(name)];
    throw_invalid("cartan." + where, argument, "(" + std::string(py::str(py::type::of(source).attr("__name__"))) + ")",
                  std::string("has no field ") + name + (with_mu ? " (give t, g, v, mu and xi, e.g. a SolveResult)"
                                                                 : " (give t, g, v and xi, e.g. a SolveResult)"));
  };
  const std::string name(argument), in = a.group + "." + where;
  api::Samples x;
  const Array t = as_array(field("t"), in, name + ".t");
  if (t.ndim() != 1) throw_invalid(in, name + ".t", "array of shape " + shape_text(t), "must be one-dimensional");
  x.t = Eigen::Map<const Eigen::VectorXd>(t.data(), t.shape(0));
  x.points = to_rows<groups::ElementOf<G>>(field("g"), in, name + ".g");
  x.v = to_rows<groups::TangentOf<G>>(field("v"), in, name + ".v");
  x.aux = to_rows<groups::CovectorOf<G>>(field("xi"), in, name + ".xi");
  x.mu = with_mu ? to_rows<groups::CovectorOf<G>>(field("mu"), in, name + ".mu")
                 : api::Table::Zero(x.t.size(), groups::CovectorOf<G>::SizeAtCompileTime);
  if (x.points.rows() != x.t.size() || x.v.rows() != x.t.size() || x.aux.rows() != x.t.size() || x.mu.rows() != x.t.size()) {
    throw_invalid("cartan." + where, argument, "(" + std::to_string(x.t.size()) + " times)",
                  with_mu ? "needs g, v, mu and xi at every time" : "needs g, v and xi at every time");
  }
  return x;
}

/// P, u, energy and cumulative_action of SolveResult from the api's along (None where there is
/// none, or for the energy and action where `with_model` is false).
template <groups::LieGroup G>
void add_along_fields(py::dict& d, std::optional<api::Along>&& along, bool with_model) {
  const py::object none = py::none();
  d["P"] = along ? py::object(rows_to_numpy<groups::AlgebraMatrixOf<G>>(std::move(along->frames))) : none;
  d["u"] = along ? py::object(rows_to_numpy<groups::TangentOf<G>>(std::move(along->u))) : none;
  d["energy"] = along && with_model ? py::object(to_numpy(along->energy)) : none;
  d["cumulative_action"] = along && with_model ? py::object(to_numpy(along->cumulative_action)) : none;
}

/// The solution as a dict of the fields of SolveResult (python/cartan/__init__.py); its samples
/// move into the arrays.
template <groups::LieGroup G>
py::dict solution_dict(api::Result&& s, const std::string& group, double lambda, double T, int N,
                       const groups::ElementOf<G>& g0, const groups::ElementOf<G>& gT, double tol) {
  py::dict d;
  add_core_fields(d, s);
  d["group"] = group;
  d["lam"] = lambda;
  d["T"] = T;
  d["N"] = N;
  d["g0"] = to_numpy(g0);
  d["gT"] = to_numpy(gT);
  d["tol"] = tol;
  api::Samples& x = s.samples;
  d["t"] = to_numpy(x.t);
  d["g"] = rows_to_numpy<groups::ElementOf<G>>(std::move(x.points));
  d["v"] = rows_to_numpy<groups::TangentOf<G>>(std::move(x.v));
  d["mu"] = rows_to_numpy<groups::CovectorOf<G>>(std::move(x.mu));
  d["xi"] = rows_to_numpy<groups::CovectorOf<G>>(std::move(x.aux));
  d["v0"] = to_numpy(s.v0);
  d["xi0"] = to_numpy(s.aux0);
  d["action"] = s.action;
  d["outer_iterations"] = s.outer_iterations;
  d["inner_iterations"] = s.inner_iterations;
  d["group_defect"] = s.collocation ? py::object(py::float_(s.collocation->group_defect)) : py::object(py::none());
  add_along_fields<G>(d, std::move(s.along), true);
  return d;
}

/// The arguments of `<Group>._solve` converted for the library (everything but the model).
template <groups::LieGroup G>
struct SolveCall {
  cartan::SolveOptions options;
  api::Guess guess;
  groups::ElementOf<G> g0, gT;

  SolveCall(const Args<G>& a, const py::object& g0_, const py::object& gT_, const SolveRequest& request,
            const py::object& v0, const py::object& xi0, const py::object& start, const py::object& progress)
      : options(solve_options(request, "cartan.solve")),
        g0(g0_.is_none() ? G::identity() : a.endpoint(g0_, "solve", "g0")),
        gT(a.endpoint(gT_, "solve", "gT")) {
    options.monitor = python_monitor(progress);
    if (!v0.is_none()) guess.v0 = models::element_numbers(a.tangent(v0, "solve", "v0"));
    if (!xi0.is_none()) guess.xi0 = models::element_numbers(a.tangent(xi0, "solve", "xi0"));
    if (!start.is_none()) guess.trajectory = samples_of<G>(start, a, "solve", "guess", false);
  }
};

/// `<Group>._solve(lagrangian, lam, T, N, g0, gT, request, v0, xi0, guess, progress)` for the
/// listed built-in models and any Python-defined Lagrangian on G, and `<Group>._validate(...)`
/// with the same arguments: the library's validate (every input error _solve would raise), no solve.
template <groups::LieGroup G, class... Models>
void bind_solvers(GroupClass<G>& group, const std::string& name, Types<Models...>) {
  const Args<G> a{name};
  group.attr("methods") = enum_words<cartan::Method>();
  // `<Group>.<entry>(lagrangian, lam, T, N, g0, gT, request, v0, xi0, guess, progress)`: run(problem,
  // call) for the problem of the model, built-in (then without the GIL) or Python-defined, and
  // reply(its value, call, lambda, T, N) with the GIL.
  const auto def_entry = [&](const char* entry, const auto& run, const auto& reply) {
    group.def_static(entry, [a, run, reply](const py::object& model, double lambda, double T, int N,
                                            const py::object& g0, const py::object& gT, const SolveRequest& request,
                                            const py::object& v0, const py::object& xi0, const py::object& guess,
                                            const py::object& progress) {
      const SolveCall<G> call(a, g0, gT, request, v0, xi0, guess, progress);
      return reply(visit_model<ErasedPythonLagrangian<G>, Models...>(model, [&](const auto& l) {
        using L = SolvedAsT<decltype(l)>;
        return run(transported::TransportedProblem<G, L>{l, lambda, T, N, call.g0, call.gT}, call);
      }), call, lambda, T, N);
    }, py::arg("lagrangian"), py::arg("lam"), py::arg("T"), py::arg("N"), py::arg("g0"), py::arg("gT"),
       py::arg("request"), py::arg("v0"), py::arg("xi0"), py::arg("guess"), py::arg("progress"));
  };
  def_entry("_solve", [](const auto& problem, const SolveCall<G>& call) {
    return api::solve(problem, call.options, call.guess, {.along = true}, "cartan.solve");
  }, [a](api::Result&& s, const SolveCall<G>& call, double lambda, double T, int N) {
    return solution_dict<G>(std::move(s), a.group, lambda, T, N, call.g0, call.gT, call.options.tol);
  });
  def_entry("_validate", [](const auto& problem, const SolveCall<G>& call) {
    api::validate(problem, call.options, call.guess, "cartan.solve");
    return true;  // visit_model returns a value
  }, [](bool, const SolveCall<G>&, double, double, int) { return py::none(); });
  group.def_static("_verify", [a](const py::object& model, const py::object& result, double lambda, double T,
                                  const py::object& g0, const py::object& gT, int order, double tol,
                                  const std::string& status) {
    const api::Samples x = samples_of<G>(result, a, "verify", "result", true);
    const groups::ElementOf<G> first = a.endpoint(g0, "verify", "g0"), last = a.endpoint(gT, "verify", "gT");
    const Status outcome = parse_enum<Status>(status, "cartan.verify");
    if (x.t.size() == 0 && outcome != Status::Converged) return report_dict(verify::unchecked_failure(outcome));
    // Every model behind the erased Lagrangian, whose verify the library compiles (the same
    // evaluations, so the same figures as the model's own type would give); N from the samples.
    return report_dict(visit_model<ErasedPythonLagrangian<G>, Models...>(model, [&](const auto& l) {
      return api::verify<G>({mechanics::ErasedLagrangian<G>(l), lambda, T, 1, first, last}, x, order, tol, outcome,
                            "cartan.verify");
    }));
  }, py::arg("lagrangian"), py::arg("result"), py::arg("lam"), py::arg("T"), py::arg("g0"), py::arg("gT"),
     py::arg("order"), py::arg("tol"), py::arg("status"));
  group.def_static("_along", [a](const py::object& model, const py::object& result, double lambda) {
    const api::Samples x = samples_of<G>(result, a, "along", "result", true);
    constexpr const char* where = "cartan.along";
    py::dict d;
    add_along_fields<G>(d, model.is_none() ? api::along<G>(nullptr, lambda, x, where)
                                           : visit_model<ErasedPythonLagrangian<G>, Models...>(model, [&](const auto& l) {
                                               const mechanics::ErasedLagrangian<G> erased(l);
                                               return api::along<G>(&erased, lambda, x, where);
                                             }),
                        !model.is_none());
    return d;
  }, py::arg("lagrangian"), py::arg("result"), py::arg("lam"));
  // `<Group>._dense(result, lam, method, times)`: the library's dense output (api/erased.hpp)
  // at the 1-d array `times`, as a dict of g, v, mu, xi with one row per time (SolveResult.sol).
  group.def_static("_dense", [a](const py::object& result, double lambda, const std::string& method, const py::object& times) {
    const api::Samples x = samples_of<G>(result, a, "sol", "result", true);
    const Array t = as_array(times, a.group + ".sol", "t");
    api::Samples d = api::dense<G>(lambda, x, parse_enum<cartan::Method>(method, "Result.sol"),
                                   std::vector<double>(t.data(), t.data() + t.size()), "Result.sol");
    py::dict out;
    out["g"] = rows_to_numpy<groups::ElementOf<G>>(std::move(d.points));
    out["v"] = rows_to_numpy<groups::TangentOf<G>>(std::move(d.v));
    out["mu"] = rows_to_numpy<groups::CovectorOf<G>>(std::move(d.mu));
    out["xi"] = rows_to_numpy<groups::CovectorOf<G>>(std::move(d.aux));
    return out;
  }, py::arg("result"), py::arg("lam"), py::arg("method"), py::arg("times"));
}

}  // namespace cartan::python
