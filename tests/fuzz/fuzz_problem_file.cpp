// libFuzzer target: the bytes of a `cartan solve --problem` file through the CLI's own path,
// parse_json -> apply_json -> validate -> the model and the boundary data (models::visit_model,
// so3_endpoints), without the solver.
// Expected rejections are std::invalid_argument; any other exception escapes and is reported by
// libFuzzer as a crash, as are sanitizer findings, leaks, timeouts and huge allocations.
// A validated spec must satisfy the invariants checked below (oracle for silent wrong answers).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "cartan/api/json_io.hpp"
#include "cartan/models/catalogue.hpp"
#include "problem_spec.hpp"
#include "solve_command.hpp"

namespace {

void require(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "fuzz_problem_file: invariant violated: %s\n", what);
    std::abort();
  }
}

/// What validate() promises and the boundary data must deliver for a spec it accepted.
void check_accepted(cartan::cli::ProblemSpec& spec) {
  require(spec.N >= 1 && std::isfinite(spec.T) && spec.T > 0 && spec.tol > 0, "validated sizes");
  const cartan::models::ModelInfo& model = cartan::models::find_model(spec.group, spec.model, "fuzz");
  const auto n = static_cast<std::size_t>(model.dim);
  require(spec.inertia.size() == n || spec.inertia.size() == n * n, "inertia has n or n^2 entries");
  require(spec.g0.size() == model.element_size, "g0 has the element's size");
  require(!spec.a0.empty() || spec.gT.size() == model.element_size, "gT has the element's size");
  // Group membership is checked by solve (as it does here; a rejection is expected), then the
  // model accepts the validated inertia and the elements are finite.
  model.check_element(spec.g0, "fuzz", "g0");
  model.check_element(cartan::cli::final_element(spec), "fuzz", "gT");
  cartan::models::visit_model(spec.group, spec.model, "fuzz", [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    (void)cartan::models::make_lagrangian<Entry>(spec.inertia, "fuzz");
    for (const auto& x : {spec.g0, cartan::cli::final_element(spec)}) {
      require(cartan::models::element_of<G>(x).allFinite(), "element is finite");
    }
    return 0;
  });
  if (spec.group != "so3") return;
  const auto ends = cartan::cli::so3_endpoints(spec);
  for (const auto* g : {&ends.g0, &ends.gT}) {
    require(g->allFinite(), "rotation is finite");
    require(((*g).transpose() * *g - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-12,
            "rotation is orthogonal");  // projected by an SVD: orthogonal to rounding
  }
  if (!spec.a0.empty()) {  // gT is the minimal rotation taking a0 to aT
    const Eigen::Vector3d a0 = Eigen::Vector3d(spec.a0.data()).stableNormalized();
    const Eigen::Vector3d aT = Eigen::Vector3d(spec.aT.data()).stableNormalized();
    require((ends.gT * a0 - aT).norm() < 1e-9, "gT maps a0 to aT");  // exp/atan2 to ~1e-15; margin
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    cartan::cli::ProblemSpec spec;
    cartan::cli::apply_json(spec, cartan::io::parse_json(text, "cartan solve: --problem"));
    cartan::cli::validate(spec);
    check_accepted(spec);
  } catch (const std::invalid_argument&) {
    // expected rejection of bad input: the CLI reports it with exit code 2
  }
  return 0;
}
