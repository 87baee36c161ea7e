#include "problem_spec.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "cartan/api/json_io.hpp"
#include "cartan/api/spaces.hpp"
#include "cartan/enum_names.hpp"
#include "cartan/errors.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/models/catalogue.hpp"
#include "cartan/principle/vocabulary.hpp"

namespace cartan::cli {

namespace {

constexpr std::string_view kWhere = "cartan solve";

[[noreturn]] void bad(const std::string& name, const std::string& value, const std::string& problem) {
  throw_invalid(kWhere, name, value, problem);
}

/// Throws naming `name` unless `values` are `size` finite numbers.
void require_size(const std::string& name, const std::vector<double>& values, std::size_t size,
                  const std::string& what) {
  if (values.size() != size) {
    bad(name, excerpt(values), "must have " + std::to_string(size) + " numbers (" + what + ")");
  }
  for (double x : values) {
    if (!std::isfinite(x)) bad(name, excerpt(values), "contains a non-finite number");
  }
}

/// Throws naming `name` when `bytes` (the estimate for `count`) exceeds kMemoryLimitBytes.
void require_memory(const std::string& name, int count, double bytes, const std::string& what) {
  if (bytes > kMemoryLimitBytes) {
    std::ostringstream message;
    message.precision(3);
    message << "needs an estimated " << bytes / (1024.0 * 1024 * 1024) << " GiB for " << what << " (limit "
            << kMemoryLimitBytes / (1024.0 * 1024 * 1024) << " GiB)";
    bad(name, std::to_string(count), message.str());
  }
}

const char* finite_value(double x) { return std::isfinite(x) ? nullptr : "is not finite"; }
const char* positive_finite(double x) { return std::isfinite(x) && x > 0 ? nullptr : "must be positive and finite"; }
const char* at_least_one(double x) { return x >= 1 ? nullptr : "must be at least 1"; }
const char* non_negative(double x) { return x >= 0 ? nullptr : "must be non-negative"; }
const char* non_negative_finite(double x) {
  return std::isfinite(x) && x >= 0 ? nullptr : "must be a non-negative number of seconds (0: no limit)";
}
const char* one_or_two(double x) { return is_scheme_order(x) ? nullptr : kSchemeOrderRule; }

/// "sphere: levi-civita; ..." for --connection's help.
std::string manifold_connections() {
  std::string out;
  for (const auto& space : api::spaces()) {
    if (space.kind == api::SpaceKind::Group) continue;  // as on a group, above
    std::string takes;
    for (const auto c : space.connections) takes.append(takes.empty() ? "" : ", ").append(to_string(c));
    out.append(out.empty() ? "" : "; ").append(space.name).append(": ").append(takes);
  }
  return out + "; a group: as above, its left-invariant connections";
}

/// Each space's one line, for --manifold's help.
std::string manifold_spaces() {
  std::string out;
  for (const auto& space : api::spaces()) out.append(out.empty() ? "" : "; ").append(space.name).append(": ").append(space.what);
  return out;
}

std::vector<ProblemField> make_fields() {
  using S = ProblemSpec;
  const std::string groups = models::group_names();
  std::string models, inertias, elements;
  for (const auto& m : models::model_infos()) {
    const std::string group = std::string(m.group);
    inertias += (inertias.empty() ? "" : "; ") + group + " " + std::string(m.model) + " " + excerpt(m.default_inertia);
    if (elements.find(group + ":") == std::string::npos) {  // once per group
      models += (models.empty() ? "" : "; ") + group + ": " + models::model_names(m.group);
      elements += (elements.empty() ? "" : "; ") + group + ": " + std::string(m.element_what);
    }
  }
  return {
      {"group", &S::group, "the group: " + groups + " (default so3)", nullptr, ProblemField::Scope::Group},
      {"model", &S::model, "the model (default the group's first; a manifold: particle): " + models, nullptr,
       ProblemField::Scope::Any},
      {"inertia", &S::inertia,
       "n numbers (the diagonal) or n*n (a symmetric positive-definite matrix, row-major), n = the algebra's dimension "
       "(default: " + inertias + ")", nullptr, ProblemField::Scope::Group},
      {"lambda", &S::lambda, "Cartan-Schouten parameter (any real; default 0.5)", finite_value, ProblemField::Scope::Any},
      {"T", &S::T, "final time (default 1)", positive_finite, ProblemField::Scope::Any},
      {"N", &S::N, "number of steps (default 100)", at_least_one, ProblemField::Scope::Any},
      {"g0", &S::g0, "initial element (default the identity): " + elements, nullptr, ProblemField::Scope::Group},
      {"gT", &S::gT, "final element, as --g0", nullptr, ProblemField::Scope::Group},  // echoed as final_element
      {"a0", &S::a0, "so3: initial direction; gT = minimal rotation taking a0 to aT", nullptr, ProblemField::Scope::Group},
      {"aT", &S::aT, "so3: final direction", nullptr, ProblemField::Scope::Group},
      {"method", &S::method,
       enum_choices<cartan::Method>() +
           " (default auto: a strategy that tries shooting, continuation in T and in lambda, "
           "collocation and multiple shooting in turn and stops at the first success; shooting: "
           "augmented shooting with an analytic Jacobian; multiple-shooting: lifted LM over --segments "
           "segments; two-level: the paper's scheme; collocation: fourth-order adaptive collocation; "
           "variational: Newton on the discrete Euler-Lagrange equations of the discrete action S_h, "
           "second order, dense, for N up to a few hundred)", nullptr, ProblemField::Scope::Any},
      {"continuation", &S::continuation,
       enum_choices<cartan::Continuation>() +
           " (default none). shooting: how to reach a problem that fails from the guess (T: from a "
           "shorter horizon; lambda: from the lambda = 0 solution); collocation: where to start again "
           "when Newton fails on the start's mesh (from that order-2 shooting solution)", nullptr, ProblemField::Scope::Any},
      {"v0", &S::v0, "guess of v(0), n numbers (shooting methods; default the geodesic velocity)", nullptr, ProblemField::Scope::Any},
      {"xi0", &S::xi0, "guess of xi(0), n numbers (shooting, multiple-shooting; default 0)", nullptr, ProblemField::Scope::Group},
      {"segments", &S::segments, "multiple-shooting only: number of segments (default about 100 steps each, at most 16)", non_negative, ProblemField::Scope::Any},
      {"order", &S::order, "1 (the paper's scheme) | 2 (second order) (default 1)", one_or_two, ProblemField::Scope::Any},
      {"tol", &S::tol, "tolerance (default " + format_value(cartan::kDefaultTol) + ")", positive_finite,
       ProblemField::Scope::Any},
      {"samples", &S::samples, "collocation only: output at this many uniform times on [0, T] (0: the final mesh)", non_negative, ProblemField::Scope::Any},
      {"max_iterations", &S::max_iterations,
       "iteration limit of each loop (default " + std::to_string(cartan::kDefaultMaxIterations) + ")",
       at_least_one, ProblemField::Scope::Any},
      {"time_limit", &S::time_limit,
       "seconds the whole solve may take, every method and attempt (default 0: no limit); past it the running method "
       "stops at its next iteration with status time-limit", non_negative_finite, ProblemField::Scope::Any},
      {"output", &S::output, "output file (default stdout)", nullptr, ProblemField::Scope::Any},
      {"connection", &S::connection,
       "groups: " + enum_choices<connections::ConnectionKind>() +
           " (cartan-schouten, the default, with --lambda; levi-civita of the left-invariant metric --metric; "
           "coefficients, the bilinear map of --alpha); the last two are solved by the general solver (methods auto, "
           "shooting, collocation). A --manifold takes those of its space (default its first): " + manifold_connections(),
       nullptr, ProblemField::Scope::Any},
      {"metric", &S::metric, "levi-civita on a group: the metric, n numbers (diagonal) or n*n (default: the inertia, or the mass)",
       nullptr, ProblemField::Scope::Any},
      {"alpha", &S::alpha,
       "coefficients: a JSON file, an n x n x n array alpha with alpha(e_i, e_j) = sum_k alpha[i][j][k] e_k",
       nullptr, ProblemField::Scope::Any},
      {"manifold", &S::manifold,
       "a space instead of a group model: the particle l = 1/2 v^T A v - V(q) on one of: " + api::space_names() +
           " (" + manifold_spaces() + "; model particle; v in the frame transported from --frame0)", nullptr,
       ProblemField::Scope::Manifold},
      {"mass", &S::mass, "manifold: A, m numbers (the diagonal) or m*m (symmetric positive definite, row-major) (default the identity)",
       nullptr, ProblemField::Scope::Manifold},
      {"gravity", &S::gravity, "manifold: G in V(q) = G q[last] (sphere, hyperbolic-plane, euclidean; default 0)", finite_value,
       ProblemField::Scope::Manifold},
      {"q0", &S::q0, "manifold: initial point (the sphere: x,y,z, normalised; the hyperbolic plane: x,y,z moved onto z^2 - x^2 - y^2 = 1; "
       "euclidean: 2 or 3 coordinates; a group: an element as --g0, default the identity)", nullptr, ProblemField::Scope::Manifold},
      {"qT", &S::qT, "manifold: final point, as q0 (required)", nullptr, ProblemField::Scope::Manifold},
      {"frame0", &S::frame0,
       "manifold: the frame at q0, its m rows e_1 .. e_m (tangent vectors at q0: 3 numbers each on a quadric), row after row "
       "(default: on the quadrics e1 towards qT along the minimal geodesic and e2 = J (q0 x e1); elsewhere the space's own basis)",
       nullptr, ProblemField::Scope::Manifold},
  };
}

/// A field's value for messages (numbers as given, lists cut by excerpt).
std::string shown(const ProblemSpec& spec, const ProblemField& field) {
  return std::visit(
      [&](auto member) -> std::string {
        const auto& value = spec.*member;
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::string>) return quote_input(value);
        else if constexpr (std::is_same_v<T, std::vector<double>>) return excerpt(value);
        else if constexpr (std::is_same_v<T, int>) return std::to_string(value);
        else return format_value(value);
      },
      field.member);
}

}  // namespace

std::string ProblemField::flag() const {
  std::string out = "--" + key;
  std::replace(out.begin(), out.end(), '_', '-');
  return out;
}

const std::vector<ProblemField>& problem_fields() {
  static const std::vector<ProblemField> fields = make_fields();
  return fields;
}

const ProblemField* find_field(std::string_view key) {
  for (const auto& f : problem_fields()) {
    if (f.key == key) return &f;
  }
  return nullptr;
}

void read_field(ProblemSpec& spec, const ProblemField& field, const nlohmann::json& value, std::string_view where) {
  std::visit(
      [&](auto member) {
        auto& target = spec.*member;
        using T = std::decay_t<decltype(target)>;
        if constexpr (std::is_same_v<T, std::string>) target = io::json_text(value, where, field.key);
        else if constexpr (std::is_same_v<T, std::vector<double>>) target = io::json_numbers(value, where, field.key);
        else if constexpr (std::is_same_v<T, int>) target = io::json_integer(value, where, field.key);
        else target = io::json_number(value, where, field.key);
      },
      field.member);
}

void check_field(const ProblemSpec& spec, const ProblemField& field, std::string_view where) {
  if (field.check == nullptr) return;
  const double value = std::visit(
      [&](auto member) -> double {
        const auto& x = spec.*member;
        if constexpr (std::is_arithmetic_v<std::decay_t<decltype(x)>>) return static_cast<double>(x);
        else return 0;  // checks are for numbers only
      },
      field.member);
  if (const char* problem = field.check(value)) throw_invalid(where, field.key, shown(spec, field), problem);
}

std::vector<double> final_element(const ProblemSpec& spec) {
  if (spec.a0.empty()) return spec.gT;
  return models::element_numbers(groups::SO3::minimal_rotation(Eigen::Vector3d(spec.a0.data()), Eigen::Vector3d(spec.aT.data())));
}

void apply_json(ProblemSpec& spec, const nlohmann::json& file) {
  if (!file.is_object()) bad("problem file", io::describe(file), "must be a JSON object");
  for (const auto& [key, value] : file.items()) {
    const ProblemField* field = find_field(key);
    if (field == nullptr) bad("key " + quote_input(key), io::describe(value), "is not a problem-file key");
    read_field(spec, *field, value, kWhere);
    spec.given.push_back(field->key);
  }
}

namespace {

void check_scope(const ProblemSpec& spec, ProblemField::Scope scope, const std::string& kind) {
  for (const auto& key : spec.given) {
    const ProblemField* field = find_field(key);
    if (field && field->scope != ProblemField::Scope::Any && field->scope != scope) {
      bad(key, shown(spec, *field), "is not an option of " + kind);
    }
  }
}

bool given(const ProblemSpec& spec, std::string_view key) {
  return std::find(spec.given.begin(), spec.given.end(), key) != spec.given.end();
}

/// The alpha file's n x n x n finite numbers, in (i, j, k) order.
std::vector<double> read_alpha(const std::string& path, std::size_t n) {
  const nlohmann::json file = io::read_json_file(path, "cartan solve: --alpha");
  const std::string shape = std::to_string(n) + " x " + std::to_string(n) + " x " + std::to_string(n);
  std::vector<double> out;
  const auto wrong = [&] { bad("alpha", quote_input(path), "must hold a " + shape + " array of numbers"); };
  if (!file.is_array() || file.size() != n) wrong();
  for (const auto& plane : file) {
    if (!plane.is_array() || plane.size() != n) wrong();
    for (const auto& row : plane) {
      const std::vector<double> numbers = io::json_numbers(row, kWhere, "alpha");
      if (numbers.size() != n) wrong();
      for (double x : numbers) {
        if (!std::isfinite(x)) bad("alpha", quote_input(path), "contains a non-finite number");
      }
      out.insert(out.end(), numbers.begin(), numbers.end());
    }
  }
  return out;
}

/// --samples: with --method collocation only, 0 or at least 2, within the memory limit.
void check_samples(const ProblemSpec& spec, cartan::Method method) {
  require_memory("samples", spec.samples, kBytesPerNode * spec.samples, "the sampled output, ~1 KiB per sample");
  if (spec.samples != 0 && method != cartan::Method::Collocation) {
    bad("samples", std::to_string(spec.samples), "is an option of --method collocation only");
  }
  if (spec.samples == 1) bad("samples", "1", "must be 0 (the final mesh) or at least 2 (uniform times on [0, T])");
}

/// --segments: at most N, within the memory of the dense multiple-shooting Jacobian.
void check_segment_count(const ProblemSpec& spec) {
  if (spec.segments > spec.N) {
    bad("segments", std::to_string(spec.segments), "must be between 1 and N (0: the default, about 100 steps each)");
  }
  require_memory("segments", spec.segments, kBytesPerSegmentSquared * spec.segments * spec.segments,
                 "the dense multiple-shooting Jacobian");
}

/// The general solver's methods (methods/manifold/solve.hpp): auto, shooting, collocation; continuation
/// none or T, with shooting and collocation only. With `lie_methods` (a group with a
/// Cartan-Schouten connection, which general::solve runs on the Lie-group kernel) also
/// multiple-shooting (with --segments), two-level and continuation in lambda.
void check_general_method(const ProblemSpec& spec, const std::string& problem, bool lie_methods = false) {
  using cartan::Method;
  const Method method = parse_enum<Method>(spec.method, "cartan solve");
  const bool lie_method = method == Method::MultipleShooting || method == Method::TwoLevel;
  if ((method != Method::Auto && method != Method::Shooting && method != Method::Collocation && !lie_method) ||
      (lie_method && !lie_methods)) {
    bad("method", quote_input(spec.method),
        "is not a method of " + problem + " (methods: auto, shooting, collocation" +
            (lie_methods ? ", multiple-shooting, two-level)" : ")"));
  }
  const cartan::Continuation continuation = parse_enum<cartan::Continuation>(spec.continuation, "cartan solve");
  if (continuation == cartan::Continuation::Lambda && (!lie_methods || method == Method::Collocation)) {
    bad("continuation", quote_input(spec.continuation),
        "is not an option of " + problem + (lie_methods ? " with --method collocation (none, T)" : " (none, T)"));
  }
  if (continuation != cartan::Continuation::None && method != Method::Shooting && method != Method::Collocation) {
    bad("continuation", quote_input(spec.continuation), "is an option of --method shooting and collocation only");
  }
  if (spec.segments != 0 && method != Method::MultipleShooting) {
    bad("segments", std::to_string(spec.segments), "is an option of --method multiple-shooting only");
  }
  check_samples(spec, method);
}

/// --connection's name and the options that belong to it: lambda (cartan-schouten), metric
/// (levi-civita), alpha (coefficients: its file read, n x n x n). Returns the connection.
connections::ConnectionKind connection_options(ProblemSpec& spec, std::size_t n) {
  using connections::ConnectionKind;
  const std::string& c = spec.connection;
  const ConnectionKind kind = parse_enum<ConnectionKind>(c, kWhere);
  const auto only = [&](ConnectionKind owner) {
    return "is an option of --connection " + std::string(to_string(owner)) + " only";
  };
  if (kind != ConnectionKind::CartanSchouten && given(spec, "lambda")) {
    bad("lambda", format_value(spec.lambda), only(ConnectionKind::CartanSchouten));
  }
  if (kind != ConnectionKind::LeviCivita && given(spec, "metric")) bad("metric", excerpt(spec.metric), only(ConnectionKind::LeviCivita));
  if (kind != ConnectionKind::Coefficients && given(spec, "alpha")) bad("alpha", quote_input(spec.alpha), only(ConnectionKind::Coefficients));
  if (kind == ConnectionKind::Coefficients && spec.alpha_values.empty()) {  // else given as numbers (a result file's echo)
    if (spec.alpha.empty()) bad("alpha", "(missing)", "is required by --connection coefficients");
    spec.alpha_values = read_alpha(spec.alpha, n);
  }
  return kind;
}

/// --connection on a group: its options, the general solver's methods where it runs, and the
/// metric (levi-civita: default the inertia). The metric's and alpha's sizes and values are the
/// library's to check (api::check, in validate).
void validate_connection(ProblemSpec& spec, std::size_t n) {
  using connections::ConnectionKind;
  const ConnectionKind kind = connection_options(spec, n);
  if (kind == ConnectionKind::CartanSchouten) return;
  check_general_method(spec, "--connection " + spec.connection);
  if (kind == ConnectionKind::LeviCivita && spec.metric.empty()) spec.metric = spec.inertia;
}

/// --manifold, a space of the library's catalogue (api/spaces.hpp): model particle, the general
/// solver's methods (auto, shooting, collocation), the connection (the space's default unless
/// given) and its options, and the library's checks of the rest (mass, gravity, points, frame0,
/// the guess); q0, qT, the connection, mass and frame0 echoed as the library poses them.
void validate_manifold_problem(ProblemSpec& spec) {
  const api::SpaceInfo& space = api::find_space(spec.manifold, kWhere);
  const std::string kind = "--manifold " + spec.manifold;
  check_scope(spec, ProblemField::Scope::Manifold, kind + " (it belongs to problems on a group)");
  // --gravity 0 too: 0 is a value, not "not given" (Python refuses gravity=0 there as well)
  if (given(spec, "gravity") && !space.gravity) {
    bad("gravity", format_value(spec.gravity),
        "does not apply on " + std::string(space.name) + " (V = G q[last] needs points that are vectors)");
  }
  if (spec.model.empty()) spec.model = "particle";
  if (spec.model != "particle") bad("model", quote_input(spec.model), "is not a model of " + kind + " (models: particle)");
  if (!given(spec, "connection")) spec.connection = std::string(to_string(space.connections.front()));
  const connections::ConnectionKind connection = parse_enum<connections::ConnectionKind>(spec.connection, kWhere);
  api::require_connection(space, connection, kWhere);
  check_general_method(spec, kind,
                       space.kind == api::SpaceKind::Group && connection == connections::ConnectionKind::CartanSchouten);
  for (const auto& field : problem_fields()) check_field(spec, field, kWhere);
  require_memory("N", spec.N, kBytesPerNode * spec.N, "the trajectory and its JSON output, ~1 KiB per step");
  check_segment_count(spec);
  std::size_t m = static_cast<std::size_t>(space.dims.front());
  if (space.kind == api::SpaceKind::Euclidean && !spec.q0.empty()) m = spec.q0.size();
  connection_options(spec, m);
  if (spec.q0.empty() && space.kind != api::SpaceKind::Group) bad("q0", "(missing)", "is required for " + kind);
  if (spec.qT.empty()) bad("qT", "(missing)", "is required for " + kind);
  const api::ManifoldProblem on = api::on_manifold(manifold_problem(spec), guess_of(spec), kWhere);
  spec.q0 = on.q0;
  spec.qT = on.qT;
  spec.mass = on.mass;
  spec.frame0 = on.frame0;
}

}  // namespace

void check_connection(ProblemSpec& spec, std::size_t n) { validate_connection(spec, n); }

void validate(ProblemSpec& spec) {
  if (is_manifold_problem(spec)) return validate_manifold_problem(spec);
  check_scope(spec, ProblemField::Scope::Group, "a problem on a group (it belongs to --manifold)");
  const models::ModelInfo& model = models::find_model(spec.group, spec.model, kWhere);
  spec.model = model.model;
  const std::size_t n = static_cast<std::size_t>(model.dim);
  const cartan::Method method = parse_enum<cartan::Method>(spec.method, "cartan solve");
  const cartan::Continuation continuation = parse_enum<cartan::Continuation>(spec.continuation, "cartan solve");
  if (continuation != cartan::Continuation::None && method != cartan::Method::Shooting && method != cartan::Method::Collocation) {
    bad("continuation", quote_input(spec.continuation), "is an option of --method shooting and collocation only");
  }
  if ((!spec.v0.empty() || !spec.xi0.empty()) &&
      (method == cartan::Method::Collocation || method == cartan::Method::Variational)) {
    bad(spec.v0.empty() ? "xi0" : "v0", excerpt(spec.v0.empty() ? spec.xi0 : spec.v0),
        "is a guess for the shooting methods, not for --method " + spec.method);
  }
  if (spec.order != 1 && method == cartan::Method::Variational) {
    bad("order", std::to_string(spec.order), "is an option of the shooting methods' schemes; --method variational is second order");
  }
  if (!spec.xi0.empty() && method == cartan::Method::TwoLevel) {
    bad("xi0", excerpt(spec.xi0), "is not a guess of --method two-level (its xi starts at 0)");
  }
  for (const auto& field : problem_fields()) check_field(spec, field, kWhere);
  require_memory("N", spec.N, kBytesPerNode * spec.N, "the trajectory and its JSON output, ~1 KiB per step");
  check_segment_count(spec);
  check_samples(spec, method);
  if (spec.segments != 0 && method != cartan::Method::MultipleShooting) {
    bad("segments", std::to_string(spec.segments), "is an option of --method multiple-shooting only");
  }
  if (spec.inertia.empty()) spec.inertia = model.default_inertia;
  validate_connection(spec, n);
  if (spec.g0.empty()) spec.g0 = model.identity;
  const bool directions = !spec.a0.empty() || !spec.aT.empty();
  if (directions) {
    if (!model.directions) bad("a0/aT", excerpt(spec.a0) + " / " + excerpt(spec.aT), "are only for --group so3");
    if (!spec.gT.empty()) bad("gT", excerpt(spec.gT), "conflicts with a0/aT: give one or the other");
    require_size("a0", spec.a0, 3, "a direction");
    require_size("aT", spec.aT, 3, "a direction");
    const Eigen::Vector3d a0(spec.a0.data()), aT(spec.aT.data());
    if (a0.stableNorm() == 0) bad("a0", excerpt(spec.a0), "has zero length");
    if (aT.stableNorm() == 0) bad("aT", excerpt(spec.aT), "has zero length");
    // stable: |a| of 1e200 or 1e-200 overflows/underflows in a plain norm
    const Eigen::Vector3d x = a0.stableNormalized(), y = aT.stableNormalized();
    if (x.cross(y).norm() < 1e-12 && x.dot(y) < 0) {
      bad("a0/aT", excerpt(spec.a0) + " / " + excerpt(spec.aT),
          "are antiparallel: the minimal rotation is not unique (give --gT instead)");
    }
  } else if (spec.gT.empty()) {
    bad("gT", "(missing)", std::string("is required") + (model.directions ? " (or a0 and aT)" : ""));
  }
  // The inertia, the connection's data, g0, gT and the guesses' sizes: the library's checks; that g0
  // and gT are elements of the group is checked by solve, so that a sweep reports it as that point's row.
  api::check(group_problem(spec), guess_of(spec), kWhere);
}

api::GroupProblem group_problem(const ProblemSpec& spec) {
  api::GroupProblem p;
  p.group = spec.group;
  p.model = spec.model;
  p.inertia = spec.inertia;
  p.connection = connection_kind(spec);
  p.lambda = spec.lambda;
  if (p.connection == connections::ConnectionKind::LeviCivita) p.metric = spec.metric;
  if (p.connection == connections::ConnectionKind::Coefficients) p.alpha = spec.alpha_values;
  p.T = spec.T;
  p.N = spec.N;
  p.g0 = spec.g0;
  p.gT = final_element(spec);
  return p;
}

api::Guess guess_of(const ProblemSpec& spec) {
  api::Guess guess;
  guess.v0 = spec.v0;
  guess.xi0 = spec.xi0;
  return guess;
}

api::ManifoldProblem manifold_problem(const ProblemSpec& spec) {
  api::ManifoldProblem p;
  p.manifold = spec.manifold;
  p.mass = spec.mass;
  p.gravity = spec.gravity;
  p.q0 = spec.q0;
  p.qT = spec.qT;
  p.T = spec.T;
  p.N = spec.N;
  p.connection = connection_kind(spec);  // validate names the space's default when none is given
  p.lambda = spec.lambda;
  p.metric = spec.metric;
  p.alpha = spec.alpha_values;
  p.frame0 = spec.frame0;
  return p;
}

}  // namespace cartan::cli
