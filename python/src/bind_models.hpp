#pragma once
// Built-in reduced Lagrangians and Hamiltonians (mechanics/), their second derivatives
// (lagrangian_hessian.hpp), and the classical Euler–Poincaré / Lie–Poisson integrators
// (euler_poincare.hpp: eq:EP-left, eq:EP-right; lie_poisson.hpp: eq:LP-left, eq:LP-right) for
// built-in and Python-defined models alike.

#include <string>

#include "bind_group.hpp"
#include "cartan/mechanics/check_lagrangian.hpp"
#include "cartan/mechanics/euler_poincare.hpp"
#include "cartan/mechanics/lagrangian_hessian.hpp"
#include "cartan/mechanics/lie_poisson.hpp"
#include "python_models.hpp"
#include "report_dict.hpp"

namespace cartan::python {

groups::Side parse_side(const std::string& side, std::string_view where);

template <class... T>
struct Types {};

/// A symmetric positive-definite inertia from a (n, n) matrix or the (n,) diagonal.
template <int N>
Eigen::Matrix<double, N, N> inertia_matrix(const py::object& inertia, std::string_view where) {
  const Array a = as_array(inertia, where, "inertia");
  if (a.ndim() == 1) return to_eigen<Eigen::Matrix<double, N, 1>>(a, where, "inertia").asDiagonal();
  return to_eigen<Eigen::Matrix<double, N, N>>(a, where, "inertia");
}

/// The class of a built-in model with its constructor and, as class attributes, its `group` and
/// `side` (the trivialisation it is reduced on).
template <class M, class Init>
py::class_<M> model_class(py::module_& m, const py::object& group, const char* name, const char* side,
                          const char* doc, Init init) {
  py::class_<M> cls(m, name, doc);
  init(cls);
  cls.attr("group") = group;
  cls.attr("side") = side;
  return cls;
}

/// Binds `name(t, g, <x>)` of a model class as f(model, t, g, x), with g an element and x an
/// algebra vector or covector, converted (and shape-checked) by `a`.
template <groups::LieGroup G, class M, class F>
void def_model_method(py::class_<M>& cls, const Args<G>& a, const char* name, const char* x, F f, const char* doc) {
  cls.def(name, [a, name, x, f](const M& model, double t, const py::object& g, const py::object& value) {
    return f(model, t, a.element(g, name, "g"), a.tangent(value, name, x));
  }, py::arg("t"), py::arg("g"), py::arg(x), doc);
}

/// value/momentum/group_gradient/velocity of a built-in Lagrangian.
template <groups::LieGroup G, mechanics::ReducedLagrangian<G> L, class Init>
void bind_lagrangian(py::module_& m, const py::object& group, const char* name, const char* side, const char* doc,
                     Init init) {
  const Args<G> a{name};
  auto cls = model_class<L>(m, group, name, side, doc, init);
  def_model_method(cls, a, "value", "v", [](const L& l, double t, const auto& g, const auto& v) {
    return l.value(t, g, v);
  }, "l(t, g, v).");
  def_model_method(cls, a, "momentum", "v", [](const L& l, double t, const auto& g, const auto& v) {
    return to_numpy(l.momentum(t, g, v));
  }, "mu = dl/dv (the reduced Legendre map).");
  def_model_method(cls, a, "group_gradient", "v", [](const L& l, double t, const auto& g, const auto& v) {
    return to_numpy(l.group_gradient(t, g, v));
  }, "zeta, the trivialised dl/dg at fixed v.");
  def_model_method(cls, a, "velocity", "mu", [](const L& l, double t, const auto& g, const auto& mu) {
    return to_numpy(l.velocity(t, g, mu));
  }, "v with momentum(t, g, v) = mu (inverse Legendre map).");
}

/// value/velocity/group_gradient of a built-in Hamiltonian.
template <groups::LieGroup G, mechanics::ReducedHamiltonian<G> H, class Init>
void bind_hamiltonian(py::module_& m, const py::object& group, const char* name, const char* side, const char* doc,
                      Init init) {
  const Args<G> a{name};
  auto cls = model_class<H>(m, group, name, side, doc, init);
  def_model_method(cls, a, "value", "mu", [](const H& h, double t, const auto& g, const auto& mu) {
    return h.value(t, g, mu);
  }, "h(t, g, mu).");
  def_model_method(cls, a, "velocity", "mu", [](const H& h, double t, const auto& g, const auto& mu) {
    return to_numpy(h.velocity(t, g, mu));
  }, "v = dh/dmu.");
  def_model_method(cls, a, "group_gradient", "mu", [](const H& h, double t, const auto& g, const auto& mu) {
    return to_numpy(h.group_gradient(t, g, mu));
  }, "The trivialised dh/dg at fixed mu.");
}

/// A reduced trajectory (lie_group_integrator.hpp) as a dict of arrays t, g, v, mu.
template <groups::LieGroup G>
py::dict trajectory_dict(const mechanics::Trajectory<G>& tr) {
  py::dict d;
  d["t"] = to_numpy(tr.t);
  d["g"] = to_numpy(tr.g);
  d["v"] = to_numpy(tr.v);
  d["mu"] = to_numpy(tr.mu);
  return d;
}

/// The samples of cartan.check_lagrangian: a count (seeded samples of options) or a sequence of
/// (t, g, v) triples.
template <groups::LieGroup G>
std::vector<mechanics::LagrangianSample<G>> check_samples(const py::object& samples, mechanics::CheckLagrangianOptions options,
                                                          const Args<G>& a) {
  const std::string where = "check_lagrangian";
  if (py::isinstance<py::int_>(samples) && !py::isinstance<py::bool_>(samples)) {
    options.samples = samples.cast<int>();
    return mechanics::lagrangian_samples<G>(options);
  }
  if (!py::isinstance<py::sequence>(samples) || py::isinstance<py::str>(samples)) {
    throw_invalid("cartan." + where, "samples", repr_of(samples), "is neither a count nor a sequence of (t, g, v)");
  }
  std::vector<mechanics::LagrangianSample<G>> out;
  for (const auto& item : py::reinterpret_borrow<py::sequence>(samples)) {
    const std::string name = "samples[" + std::to_string(out.size()) + "]";
    if (!py::isinstance<py::sequence>(item) || py::len(item) != 3) {
      throw_invalid("cartan." + where, name, repr_of(item), "is not a triple (t, g, v)");
    }
    const py::sequence triple = py::reinterpret_borrow<py::sequence>(item);
    const py::object t = triple[0];
    if (!py::isinstance<py::float_>(t) && !py::isinstance<py::int_>(t)) {
      throw_invalid("cartan." + where, name + "[0]", repr_of(t), "is not a number (the time t)");
    }
    out.push_back({t.cast<double>(), a.element(triple[1], where, name + "[1]"), a.tangent(triple[2], where, name + "[2]")});
  }
  return out;
}

/// Static methods of the group class that take a model, built-in (one of the listed types) or
/// written in Python: _euler_poincare, _lie_poisson, _lagrangian_hessian, _check_lagrangian.
template <groups::LieGroup G, class... Lagrangians, class... Hamiltonians>
void bind_mechanics(GroupClass<G>& group, const std::string& name, Types<Lagrangians...>, Types<Hamiltonians...>) {
  const Args<G> a{name};
  group.def_static("_euler_poincare", [a](const std::string& side, const py::object& model, const py::object& g0,
                                          const py::object& v0, double T, int steps) {
    const groups::Side s = parse_side(side, a.group + ".euler_poincare");
    const groups::ElementOf<G> g = a.element(g0, "euler_poincare", "g0");
    const groups::TangentOf<G> v = a.tangent(v0, "euler_poincare", "v0");
    return trajectory_dict<G>(visit_model<PythonLagrangian<G>, Lagrangians...>(
        model, [&](const auto& l) { return mechanics::euler_poincare<G>(s, l, g, v, T, steps); }));
  }, py::arg("side"), py::arg("lagrangian"), py::arg("g0"), py::arg("v0"), py::arg("T"), py::arg("steps"));
  group.def_static("_lie_poisson", [a](const std::string& side, const py::object& model, const py::object& g0,
                                       const py::object& mu0, double T, int steps) {
    const groups::Side s = parse_side(side, a.group + ".lie_poisson");
    const groups::ElementOf<G> g = a.element(g0, "lie_poisson", "g0");
    const groups::CovectorOf<G> mu = a.tangent(mu0, "lie_poisson", "mu0");
    return trajectory_dict<G>(visit_model<PythonHamiltonian<G>, Hamiltonians...>(
        model, [&](const auto& h) { return mechanics::lie_poisson<G>(s, h, g, mu, T, steps); }));
  }, py::arg("side"), py::arg("hamiltonian"), py::arg("g0"), py::arg("mu0"), py::arg("T"), py::arg("steps"));
  group.def_static("_lagrangian_hessian", [a](const py::object& model, double t, const py::object& g0,
                                              const py::object& v0) {
    const groups::ElementOf<G> g = a.element(g0, "lagrangian_hessian", "g");
    const groups::TangentOf<G> v = a.tangent(v0, "lagrangian_hessian", "v");
    const mechanics::LagrangianHessian<G> h = visit_model<PythonLagrangian<G>, Lagrangians...>(
        model, [&](const auto& l) { return mechanics::lagrangian_hessian<G>(l, t, g, v); });
    py::dict d;
    d["momentum_v"] = to_numpy(h.momentum_v);
    d["momentum_g"] = to_numpy(h.momentum_g);
    d["gradient_v"] = to_numpy(h.gradient_v);
    d["gradient_g"] = to_numpy(h.gradient_g);
    return d;
  }, py::arg("lagrangian"), py::arg("t"), py::arg("g"), py::arg("v"));
  group.def_static("_check_lagrangian", [a](const py::object& model, const py::object& samples, std::uint32_t seed,
                                            double scale, const std::string& side) {
    mechanics::CheckLagrangianOptions options;
    options.seed = seed;
    options.scale = scale;
    options.side = parse_side(side, "cartan.check_lagrangian");
    const auto points = check_samples<G>(samples, options, a);
    return check_report_dict(visit_model<CheckedPythonLagrangian<G>, Lagrangians...>(
        model, [&](const auto& l) { return mechanics::check_lagrangian<G>(l, points, options.side); }));
  }, py::arg("lagrangian"), py::arg("samples"), py::arg("seed"), py::arg("scale"), py::arg("side"));
}

}  // namespace cartan::python
