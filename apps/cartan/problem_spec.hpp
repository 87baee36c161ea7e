#pragma once
// One validated description of a `cartan solve` problem, built from a JSON problem file and/or
// command-line flags (flags override the file). Validation happens here, at the edge
// (DESIGN.md); everything below may assume valid input.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "cartan/api/solve.hpp"
#include "cartan/connections/connection_kind.hpp"
#include "cartan/principle/vocabulary.hpp"

namespace cartan::cli {

struct ProblemSpec {
  /// Empty: a problem on a group (group, model, inertia, lambda, g0, gT); a space of the library's
  /// catalogue (api/spaces.hpp): the particle on it (api::ManifoldProblem: model particle, mass,
  /// gravity, the connection and its options, q0, qT, frame0).
  std::string manifold;
  std::string group = "so3";            ///< a group of the model table (models/catalogue.hpp)
  std::string model;                    ///< a model of the group; empty: the group's first (validate fills it)
  std::vector<double> inertia;          ///< n numbers (diagonal) or n^2 (row-major); default: the model's
  double lambda = 0.5;
  double T = 1.0;
  int N = 100;
  std::vector<double> g0;               ///< the element's numbers (models/catalogue.hpp); default the identity
  std::vector<double> gT;
  std::vector<double> a0, aT;           ///< so3 only: gT = minimal rotation taking a0 to aT
  std::string method = "auto";          ///< a Method word (principle/vocabulary.hpp): auto | shooting | multiple-shooting | two-level | collocation | variational
  int order = 1;
  double tol = cartan::kDefaultTol;
  int samples = 0;                      ///< collocation: output at this many uniform times (0: the final mesh)
  std::string continuation = "none";    ///< a Continuation word: none | T | lambda (shooting and collocation only)
  std::vector<double> v0, xi0;          ///< optional guesses of v(0) and xi(0) (n numbers each)
  int segments = 0;                     ///< multiple shooting: number of segments (0: default_segments(N))
  int max_iterations = cartan::kDefaultMaxIterations;
  double time_limit = 0;                ///< seconds; 0: no limit
  std::string output;                   ///< empty: stdout
  std::vector<double> mass;             ///< manifold: A, m or m^2 numbers (default the identity; filled by validate)
  double gravity = 0;                   ///< manifold: G
  std::vector<double> q0, qT;           ///< manifold: endpoints (moved onto the manifold by validate)
  std::vector<double> frame0;           ///< manifold: the rows e_1 .. e_m of the frame at q0 (empty: the default; filled by validate)
  std::string connection{to_string(connections::ConnectionKind::CartanSchouten)};  ///< groups: a ConnectionKind word
  std::vector<double> metric;           ///< levi-civita: n or n^2 numbers (default: the inertia)
  std::string alpha;                    ///< coefficients: a JSON file alpha[i][j][k], alpha(e_i, e_j) = sum_k alpha[i][j][k] e_k
  std::vector<double> alpha_values;     ///< the file's n^3 numbers in (i, j, k) order (filled by validate)
  std::vector<std::string> given;       ///< the keys set by the problem file or flags (validate's scope check)
};

/// One field of a problem: its JSON key (the flag is --key with '_' written '-'), the ProblemSpec
/// member it fills (its type is the field's kind: text, number, integer or a list of numbers),
/// its help, and for numbers the check of its value. The one list of the problem's fields:
/// parsed from problem files and flags, checked by validate. (What a result file echoes of the
/// problem is the library's: cartan/api/result_file.hpp.)
struct ProblemField {
  /// Which problems the field belongs to: every problem, those on a group, or those on a --manifold.
  enum class Scope { Any, Group, Manifold };
  using Member = std::variant<std::string ProblemSpec::*, double ProblemSpec::*, int ProblemSpec::*,
                              std::vector<double> ProblemSpec::*>;
  std::string key;
  Member member;
  std::string help;
  /// A number's problem ("must be positive and finite"), or nullptr when the value is fine.
  const char* (*check)(double) = nullptr;
  Scope scope = Scope::Any;

  std::string flag() const;  ///< "--max-iterations" for max_iterations
};

/// Every field, in the order of `cartan solve --help`.
const std::vector<ProblemField>& problem_fields();
/// The field with this JSON key, or nullptr.
const ProblemField* find_field(std::string_view key);

/// Sets the field from a JSON value (json_io.hpp's typed readers). Throws std::invalid_argument
/// "<where>: <key> = <value> <problem>" for a wrong type.
void read_field(ProblemSpec& spec, const ProblemField& field, const nlohmann::json& value, std::string_view where);
/// Throws std::invalid_argument "<where>: <key> = <value> <problem>" when field.check rejects it.
void check_field(const ProblemSpec& spec, const ProblemField& field, std::string_view where);

/// Memory limit of one `cartan solve` run, checked by validate() so that a huge N, --samples or
/// --segments is refused with a message instead of ending in std::bad_alloc or the OOM killer.
inline constexpr double kMemoryLimitBytes = 4.0 * 1024 * 1024 * 1024;
/// Peak memory per stored node (trajectory, solver copies, JSON tree and text), rounded up from
/// the measured peak RSS / N (bench/README.md, "memory per node").
inline constexpr double kBytesPerNode = 1024;
/// Multiple shooting's dense lifted algebra: (12 M)^2 doubles per matrix for M segments, about 4
/// such matrices alive at once (Jacobian, normal matrix, its damped copy and factorisation).
inline constexpr double kBytesPerSegmentSquared = 4 * 144 * 8;

/// Overwrites fields of `spec` with the keys present in `file` (a JSON object). Unknown keys and
/// wrong types throw std::invalid_argument naming the key.
void apply_json(ProblemSpec& spec, const nlohmann::json& file);

/// True for a problem on a group with a connection other than Cartan–Schouten (the general solver).
inline bool is_general_connection(const ProblemSpec& spec) {
  return spec.connection != to_string(connections::ConnectionKind::CartanSchouten);
}

/// The connection of a validated group spec (validate checked the word).
inline connections::ConnectionKind connection_kind(const ProblemSpec& spec) {
  return parse_enum<connections::ConnectionKind>(spec.connection, "cartan solve");
}

/// True for a problem on a manifold (spec.manifold set) rather than on a group.
inline bool is_manifold_problem(const ProblemSpec& spec) { return !spec.manifold.empty(); }

/// Checks every field and fills defaults (model: the group's first; inertia: the model's;
/// g0 = identity). The inertia is checked by building the library's model; that g0 and gT are
/// group elements is checked by solve (solve_command.hpp), so that `cartan sweep` reports such a
/// point as an error row. Throws std::invalid_argument naming the first bad value.
void validate(ProblemSpec& spec);

/// The connection part of validate for a group of algebra dimension n: the connection's name, the
/// options that belong to it, the metric (levi-civita) and alpha (coefficients: alpha_values if set,
/// else read from the file alpha). Throws std::invalid_argument naming the first bad value.
void check_connection(ProblemSpec& spec, std::size_t n);

/// The library's description of a spec on a group (gT: final_element) or on a manifold
/// (cartan/api/solve.hpp): what validate checks through api::check and solve solves.
api::GroupProblem group_problem(const ProblemSpec& spec);
api::ManifoldProblem manifold_problem(const ProblemSpec& spec);
/// The spec's guesses of v(0) and xi(0).
api::Guess guess_of(const ProblemSpec& spec);

/// The final element of a validated spec as its numbers (so3: row-major): gT, or for so3 with
/// a0/aT the minimal rotation taking a0 to aT.
std::vector<double> final_element(const ProblemSpec& spec);


}  // namespace cartan::cli
