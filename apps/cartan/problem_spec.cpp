#include "problem_spec.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "cartan/errors.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/transported/method.hpp"

namespace cartan::cli {

namespace {

[[noreturn]] void bad(const std::string& name, const std::string& value, const std::string& problem) {
  throw_invalid("cartan solve", name, value, problem);
}

std::string join(const std::vector<double>& values) {
  std::ostringstream out;
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? "," : "") << format_value(values[i]);
  return out.str();
}

std::vector<double> json_numbers(const nlohmann::json& value, const std::string& key) {
  if (value.is_string()) return parse_list(value.get<std::string>(), key);
  if (!value.is_array()) bad(key, value.dump(), "must be a list of numbers");
  std::vector<double> out;
  for (const auto& x : value) {
    if (x.is_array()) {
      for (const auto& y : x) {  // a matrix given as rows
        if (!y.is_number()) bad(key, value.dump(), "must contain only numbers");
        out.push_back(y.get<double>());
      }
    } else {
      if (!x.is_number()) bad(key, value.dump(), "must contain only numbers");
      out.push_back(x.get<double>());
    }
  }
  return out;
}

double json_number(const nlohmann::json& value, const std::string& key) {
  if (!value.is_number()) bad(key, value.dump(), "must be a number");
  return value.get<double>();
}

int json_int(const nlohmann::json& value, const std::string& key) {
  if (!value.is_number_integer() && !(value.is_number() && std::floor(value.get<double>()) == value.get<double>())) {
    bad(key, value.dump(), "must be an integer");
  }
  const double x = value.get<double>();
  if (std::abs(x) > 2e9) bad(key, value.dump(), "is out of range");
  return static_cast<int>(x);
}

std::string json_string(const nlohmann::json& value, const std::string& key) {
  if (!value.is_string()) bad(key, value.dump(), "must be a string");
  return value.get<std::string>();
}

void require_one_of(const std::string& name, const std::string& value, const std::vector<std::string>& choices) {
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    bad(name, quote_input(value), "is not one of: " + list);
  }
}

void require_size(const std::string& name, const std::vector<double>& values, std::size_t size,
                  const std::string& what) {
  if (values.size() != size) {
    bad(name, join(values), "must have " + std::to_string(size) + " numbers (" + what + ")");
  }
  for (double x : values) {
    if (!std::isfinite(x)) bad(name, join(values), "contains a non-finite number");
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

}  // namespace

std::vector<double> final_element(const ProblemSpec& spec) {
  if (spec.a0.empty()) return spec.gT;
  const groups::SO3::Element r = groups::SO3::minimal_rotation(Eigen::Vector3d(spec.a0.data()), Eigen::Vector3d(spec.aT.data()));
  std::vector<double> out(9);
  for (int i = 0; i < 9; ++i) out[static_cast<std::size_t>(i)] = r(i / 3, i % 3);  // row-major
  return out;
}

nlohmann::json result_header(const ProblemSpec& spec, const std::string& status, const std::string& message,
                             const std::string& method, int order, const std::string& branch) {
  return {{"status", status}, {"message", message}, {"group", spec.group}, {"model", spec.model},
          {"lambda", spec.lambda}, {"T", spec.T}, {"N", spec.N}, {"method", method}, {"order", order},
          {"branch", branch}, {"inertia", spec.inertia}, {"g0", spec.g0}, {"gT", final_element(spec)},
          {"tol", spec.tol}};
}

std::vector<double> parse_list(const std::string& text, const std::string& name) {
  std::vector<double> out;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    const std::string trimmed = first == std::string::npos ? "" : item.substr(first, last - first + 1);
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(trimmed, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (trimmed.empty() || used != trimmed.size()) bad(name, quote_input(text), "is not a comma-separated list of numbers");
    out.push_back(value);
  }
  if (out.empty()) bad(name, quote_input(text), "is empty");
  return out;
}

void apply_json(ProblemSpec& spec, const nlohmann::json& file) {
  if (!file.is_object()) bad("problem file", file.dump().substr(0, 80), "must be a JSON object");
  for (const auto& [key, value] : file.items()) {
    if (key == "group") spec.group = json_string(value, key);
    else if (key == "model") spec.model = json_string(value, key);
    else if (key == "inertia") spec.inertia = json_numbers(value, key);
    else if (key == "lambda") spec.lambda = json_number(value, key);
    else if (key == "T") spec.T = json_number(value, key);
    else if (key == "N") spec.N = json_int(value, key);
    else if (key == "g0") spec.g0 = json_numbers(value, key);
    else if (key == "gT") spec.gT = json_numbers(value, key);
    else if (key == "a0") spec.a0 = json_numbers(value, key);
    else if (key == "aT") spec.aT = json_numbers(value, key);
    else if (key == "method") spec.method = json_string(value, key);
    else if (key == "order") spec.order = json_int(value, key);
    else if (key == "tol") spec.tol = json_number(value, key);
    else if (key == "samples") spec.samples = json_int(value, key);
    else if (key == "segments") spec.segments = json_int(value, key);
    else if (key == "continuation") spec.continuation = json_string(value, key);
    else if (key == "v0") spec.v0 = json_numbers(value, key);
    else if (key == "xi0") spec.xi0 = json_numbers(value, key);
    else if (key == "max_iterations") spec.max_iterations = json_int(value, key);
    else if (key == "output") spec.output = json_string(value, key);
    else bad("key " + quote_input(key), quote_input(value.dump()), "is not a problem-file key");
  }
}

void validate(ProblemSpec& spec) {
  require_one_of("group", spec.group, {"so3", "heisenberg"});
  require_one_of("model", spec.model, spec.group == "so3" ? std::vector<std::string>{"free-rigid-body", "oscillator"}
                                                           : std::vector<std::string>{"oscillator"});
  const transported::Method method = parse_enum<transported::Method>(spec.method, "cartan solve");
  const transported::Continuation continuation = parse_enum<transported::Continuation>(spec.continuation, "cartan solve");
  if (continuation != transported::Continuation::None && method != transported::Method::Shooting && method != transported::Method::Collocation) {
    bad("continuation", quote_input(spec.continuation), "is an option of --method shooting and collocation only");
  }
  if (!spec.v0.empty()) require_size("v0", spec.v0, 3, "a guess of v(0)");
  if (!spec.xi0.empty()) require_size("xi0", spec.xi0, 3, "a guess of xi(0)");
  if ((!spec.v0.empty() || !spec.xi0.empty()) && method == transported::Method::Collocation) {
    bad(spec.v0.empty() ? "xi0" : "v0", join(spec.v0.empty() ? spec.xi0 : spec.v0),
        "is a guess for the shooting methods, not for --method collocation");
  }
  if (!spec.xi0.empty() && method == transported::Method::TwoLevel) {
    bad("xi0", join(spec.xi0), "is not a guess of --method two-level (its xi starts at 0)");
  }
  if (spec.order != 1 && spec.order != 2) bad("order", std::to_string(spec.order), "must be 1 or 2");
  if (!std::isfinite(spec.lambda)) bad("lambda", format_value(spec.lambda), "is not finite");
  if (!(std::isfinite(spec.T) && spec.T > 0)) bad("T", format_value(spec.T), "must be positive and finite");
  if (spec.N < 1) bad("N", std::to_string(spec.N), "must be at least 1");
  require_memory("N", spec.N, kBytesPerNode * spec.N, "the trajectory and its JSON output, ~1 KiB per step");
  if (!(std::isfinite(spec.tol) && spec.tol > 0)) bad("tol", format_value(spec.tol), "must be positive and finite");
  if (spec.max_iterations < 1) bad("max_iterations", std::to_string(spec.max_iterations), "must be at least 1");
  if (spec.samples < 0) bad("samples", std::to_string(spec.samples), "must be non-negative");
  if (spec.segments < 0 || spec.segments > spec.N) {
    bad("segments", std::to_string(spec.segments), "must be between 1 and N (0: the default, about 100 steps each)");
  }
  require_memory("samples", spec.samples, kBytesPerNode * spec.samples, "the sampled output, ~1 KiB per sample");
  require_memory("segments", spec.segments, kBytesPerSegmentSquared * spec.segments * spec.segments,
                 "the dense multiple-shooting Jacobian");
  if (spec.samples != 0 && method != transported::Method::Collocation) {
    bad("samples", std::to_string(spec.samples), "is an option of --method collocation only");
  }
  if (spec.segments != 0 && method != transported::Method::MultipleShooting) {
    bad("segments", std::to_string(spec.segments), "is an option of --method multiple-shooting only");
  }
  if (spec.samples == 1) bad("samples", "1", "must be 0 (the final mesh) or at least 2 (uniform times on [0, T])");
  if (spec.inertia.empty()) spec.inertia = spec.group == "so3" ? std::vector<double>{2, 3, 4} : std::vector<double>{1, 1, 1};
  require_size("inertia", spec.inertia, 3, "the diagonal of the inertia");
  for (double x : spec.inertia) {
    if (!(x > 0)) bad("inertia", join(spec.inertia), "is not positive definite (entries must be > 0)");
  }
  const std::size_t element_size = spec.group == "so3" ? 9 : 3;
  const std::string element_what = spec.group == "so3" ? "a rotation matrix, row-major" : "coordinates a,b,c";
  if (spec.g0.empty()) {
    spec.g0 = spec.group == "so3" ? std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1} : std::vector<double>{0, 0, 0};
  }
  require_size("g0", spec.g0, element_size, element_what);
  const bool directions = !spec.a0.empty() || !spec.aT.empty();
  if (directions) {
    if (spec.group != "so3") bad("a0/aT", join(spec.a0) + " / " + join(spec.aT), "are only for --group so3");
    if (!spec.gT.empty()) bad("gT", join(spec.gT), "conflicts with a0/aT: give one or the other");
    require_size("a0", spec.a0, 3, "a direction");
    require_size("aT", spec.aT, 3, "a direction");
    const Eigen::Vector3d a0(spec.a0.data()), aT(spec.aT.data());
    if (a0.stableNorm() == 0) bad("a0", join(spec.a0), "has zero length");
    if (aT.stableNorm() == 0) bad("aT", join(spec.aT), "has zero length");
    // stable: |a| of 1e200 or 1e-200 overflows/underflows in a plain norm
    const Eigen::Vector3d x = a0.stableNormalized(), y = aT.stableNormalized();
    if (x.cross(y).norm() < 1e-12 && x.dot(y) < 0) {
      bad("a0/aT", join(spec.a0) + " / " + join(spec.aT),
          "are antiparallel: the minimal rotation is not unique (give --gT instead)");
    }
  } else {
    if (spec.gT.empty()) bad("gT", "(missing)", "is required (or, for so3, a0 and aT)");
    require_size("gT", spec.gT, element_size, element_what);
  }
}

}  // namespace cartan::cli
