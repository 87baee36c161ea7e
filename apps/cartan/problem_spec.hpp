#pragma once
// One validated description of a `cartan solve` problem, built from a JSON problem file and/or
// command-line flags (flags override the file). Validation happens here, at the edge
// (DESIGN.md); everything below may assume valid input.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace cartan::cli {

struct ProblemSpec {
  std::string group = "so3";            ///< so3 | heisenberg
  std::string model = "free-rigid-body";  ///< free-rigid-body | oscillator
  std::vector<double> inertia;          ///< 3 numbers (diagonal); default 2,3,4 (so3), 1,1,1 (heisenberg)
  double lambda = 0.5;
  double T = 1.0;
  int N = 100;
  std::vector<double> g0;               ///< so3: 9 numbers row-major; heisenberg: a,b,c
  std::vector<double> gT;
  std::vector<double> a0, aT;           ///< so3 only: gT = minimal rotation taking a0 to aT
  std::string method = "auto";          ///< a Method word (transported/method.hpp): auto | shooting | multiple-shooting | two-level | collocation
  int order = 1;
  double tol = 1e-10;
  int samples = 0;                      ///< collocation: output at this many uniform times (0: the final mesh)
  std::string continuation = "none";    ///< a Continuation word: none | T | lambda (shooting and collocation only)
  std::vector<double> v0, xi0;          ///< optional guesses of v(0) and xi(0) (3 numbers each)
  int segments = 0;                     ///< multiple shooting: number of segments (0: default_segments(N))
  int max_iterations = 200;
  std::string output;                   ///< empty: stdout
};

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

/// Parses "x,y,z" into numbers; throws std::invalid_argument naming `name` on a bad entry.
std::vector<double> parse_list(const std::string& text, const std::string& name);

/// Checks every field and fills defaults (inertia; g0 = identity). Throws std::invalid_argument
/// naming the first bad value.
void validate(ProblemSpec& spec);

/// The final element of a validated spec as its numbers (so3: row-major): gT, or for so3 with
/// a0/aT the minimal rotation taking a0 to aT.
std::vector<double> final_element(const ProblemSpec& spec);

/// The part of a `cartan solve` result every method shares: status, message, group, model,
/// lambda, T, N, method, order, branch, and what rebuilds the problem (`cartan verify`):
/// inertia, g0, gT (final_element), tol. Each method adds its trajectory and diagnostics.
nlohmann::json result_header(const ProblemSpec& spec, const std::string& status, const std::string& message,
                             const std::string& method, int order, const std::string& branch);


}  // namespace cartan::cli
