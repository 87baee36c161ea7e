// The general transported-velocity solve (include/cartan/methods/solve.hpp) and its verifier on
// the manifold classes of bind_manifolds.cpp, in their own translation unit.
//
// `_solve_general(manifold, ...)`: general::solve with the vocabulary of cartan.solve. Every
// Lagrangian (a KineticPotential<M>, l = 1/2 v^T A v - V(q) with V built in (gravity) or a Python
// callable, or a Lagrangian object written in Python) goes behind general::ErasedLagrangian<M>,
// whose solve and verify the library compiles once per manifold (cartan/kernels/manifold/compiled.hpp);
// general_binding.hpp converts the arguments and the result. Solves without Python callbacks
// release the GIL; with them, the GIL is held and the first callback error is re-raised after the
// solver returns (python_models.hpp).

#include <cstdint>

#include "general_binding.hpp"
#include "option_words.hpp"
#include "report_dict.hpp"

namespace cartan::python {

namespace {

using namespace general_binding;
using manifolds::HyperbolicPlane;
using manifolds::Sphere;

/// f(manifold, chart callbacks) for the C++ manifold behind a Python manifold object; the
/// callbacks are those of a cartan.Chart, null for the built-in manifolds.
template <class F>
py::dict visit_manifold(const py::handle& object, F&& f) {
  const auto built_in = [&](const auto& m) { return f(m, static_cast<ChartCallbacks*>(nullptr)); };
  if (py::isinstance<Sphere>(object)) return built_in(object.cast<const Sphere&>());
  if (py::isinstance<HyperbolicPlane>(object)) return built_in(object.cast<const HyperbolicPlane&>());
  if (py::isinstance<EuclideanManifold>(object)) return visit_holder(object.cast<const EuclideanManifold&>(), built_in);
  if (py::isinstance<AnyGroupManifold>(object)) return visit_holder(object.cast<const AnyGroupManifold&>(), built_in);
  if (py::isinstance<ChartManifold>(object)) {
    const auto& chart = object.cast<const ChartManifold&>();
    return visit_holder(chart, [&](const auto& m) { return f(m, chart.callbacks.get()); });
  }
  throw_invalid(kWhere, "manifold", repr_of(object),
                "is not a manifold (cartan.Sphere, HyperbolicPlane, Euclidean, GroupManifold, Chart)");
}

}  // namespace

void bind_general(py::module_& m) {
  py::class_<GeneralRequest> request_class(m, "_GeneralRequest");
  def_option_words(request_class)
      .def(py::init<>())
      .def_readwrite("T", &GeneralRequest::T)
      .def_readwrite("N", &GeneralRequest::N)
      .def_readwrite("q0", &GeneralRequest::q0)
      .def_readwrite("qT", &GeneralRequest::qT)
      .def_readwrite("inertia", &GeneralRequest::inertia)
      .def_readwrite("potential", &GeneralRequest::potential)
      .def_readwrite("potential_gradient", &GeneralRequest::potential_gradient)
      .def_readwrite("gravity", &GeneralRequest::gravity)
      .def_readwrite("lagrangian", &GeneralRequest::lagrangian)
      .def_readwrite("frame0", &GeneralRequest::frame0)
      .def_readwrite("v0", &GeneralRequest::v0)
      .def_readwrite("Xi0", &GeneralRequest::Xi0)
      .def_readwrite("progress", &GeneralRequest::progress)
      .def_readwrite("guess", &GeneralRequest::guess);
  m.def("_solve_general", [](const py::object& manifold, const GeneralRequest& request) {
    return visit_manifold(manifold, [&](const auto& mf, ChartCallbacks* chart) { return solve_on(mf, request, chart); });
  }, py::arg("manifold"), py::arg("request"));
  m.def("_validate_general", [](const py::object& manifold, const GeneralRequest& request) {
    visit_manifold(manifold, [&](const auto& mf, ChartCallbacks*) {
      validate_on(mf, request);
      return py::dict();  // the visitor's type; nothing to return
    });
  }, py::arg("manifold"), py::arg("request"));
  m.def("_along_general", [](const py::object& manifold, const GeneralRequest& request, const py::dict& fields,
                             bool named_only) {
    return visit_manifold(manifold, [&](const auto& mf, ChartCallbacks* chart) {
      return run_on_chart(chart, [&] { return along_on(mf, request, fields, named_only); });
    });
  }, py::arg("manifold"), py::arg("request"), py::arg("fields"), py::arg("named_only"));
  m.def("_verify_general", [](const py::object& manifold, const GeneralRequest& request, const py::object& result) {
    return visit_manifold(manifold, [&](const auto& mf, ChartCallbacks* chart) {
      return verify_on(mf, request, result, chart);
    });
  }, py::arg("manifold"), py::arg("request"), py::arg("result"));
  m.def("_check_general_lagrangian", [](const py::object& manifold, const GeneralRequest& request, const py::object& samples,
                                        std::uint32_t seed, double scale, const py::object& q) {
    mechanics::CheckLagrangianOptions options;
    options.seed = seed;
    options.scale = scale;
    return visit_manifold(manifold, [&](const auto& mf, ChartCallbacks* chart) {
      return check_report_dict(check_on(mf, request, samples, options, q, chart));
    });
  }, py::arg("manifold"), py::arg("request"), py::arg("samples"), py::arg("seed"), py::arg("scale"), py::arg("q"));
}

}  // namespace cartan::python
