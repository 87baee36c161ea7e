#include "result_reader.hpp"

#include "cartan/status.hpp"
#include "cartan/transported/method.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cartan/errors.hpp"
#include "problem_spec.hpp"

namespace cartan::cli {

namespace {

constexpr const char* kWhere = "cartan verify";

/// The first and last times must match 0 and T to this fraction of T (shooting accumulates t_k
/// by adding h, which leaves a rounding error of about N eps T).
constexpr double kTimeSpanTolerance = 1e-6;

[[noreturn]] void bad(const std::string& name, const std::string& value, const std::string& problem) {
  throw_invalid(kWhere, name, value, problem);
}

/// A short description of a JSON value for messages: scalars printed, containers by type and
/// size (never dumped: a hostile document may be huge or deeply nested).
std::string describe(const nlohmann::json& value) {
  if (value.is_number()) return format_value(value.get<double>());
  if (value.is_string()) {
    const auto& s = value.get_ref<const std::string&>();
    return "\"" + (s.size() > 40 ? s.substr(0, 40) + "..." : s) + "\"";
  }
  if (value.is_array()) return "(an array of " + std::to_string(value.size()) + " entries)";
  if (value.is_object()) return "(an object)";
  return std::string("(") + value.type_name() + ")";
}

const nlohmann::json& require_key(const nlohmann::json& j, const std::string& key) {
  const auto it = j.find(key);
  if (it == j.end()) bad(key, "(missing)", "is required in a result file");
  return *it;
}

double finite_number(const nlohmann::json& value, const std::string& name) {
  if (!value.is_number()) bad(name, describe(value), "must be a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) bad(name, describe(value), "is not finite");
  return x;
}

double positive_number(const nlohmann::json& value, const std::string& name) {
  const double x = finite_number(value, name);
  if (!(x > 0)) bad(name, describe(value), "must be positive");
  return x;
}

int integer(const nlohmann::json& value, const std::string& name) {
  const double x = finite_number(value, name);
  if (std::floor(x) != x) bad(name, describe(value), "must be an integer");
  if (std::abs(x) > 2e9) bad(name, describe(value), "is out of range");
  return static_cast<int>(x);
}

std::string one_of(const nlohmann::json& value, const std::string& name, const std::vector<std::string>& choices) {
  if (!value.is_string()) bad(name, describe(value), "must be a string");
  const auto& s = value.get_ref<const std::string&>();
  if (std::find(choices.begin(), choices.end(), s) == choices.end()) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    bad(name, describe(value), "is not one of: " + list);
  }
  return s;
}

/// A flat list of exactly `size` finite numbers.
Eigen::VectorXd numbers(const nlohmann::json& value, const std::string& name, std::size_t size) {
  if (!value.is_array() || value.size() != size) {
    bad(name, describe(value), "must be a list of " + std::to_string(size) + " numbers");
  }
  Eigen::VectorXd out(static_cast<Eigen::Index>(size));
  for (std::size_t i = 0; i < size; ++i) {
    out[static_cast<Eigen::Index>(i)] = finite_number(value[i], name + "[" + std::to_string(i) + "]");
  }
  return out;
}

/// Throws unless the 9 row-major numbers are a rotation within kResultRotationTolerance.
void require_rotation(const Eigen::VectorXd& rowmajor, const std::string& name) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 9; ++i) r(i / 3, i % 3) = rowmajor[i];
  const double orthogonality = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality > kResultRotationTolerance || std::abs(r.determinant() - 1) > kResultRotationTolerance) {
    bad(name, format_value(r),
        "is not a rotation (max|R^T R - I| = " + format_value(orthogonality) + ", det = " + format_value(r.determinant()) +
            ", tolerance " + format_value(kResultRotationTolerance) + ")");
  }
}

/// `rows` rows of `width` finite numbers each, as a rows x width matrix.
Eigen::MatrixXd table(const nlohmann::json& value, const std::string& name, std::size_t rows, std::size_t width) {
  if (!value.is_array() || value.size() != rows) {
    bad(name, describe(value), "must have " + std::to_string(rows) + " rows (one per entry of t)");
  }
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(width));
  for (std::size_t k = 0; k < rows; ++k) {
    out.row(static_cast<Eigen::Index>(k)) = numbers(value[k], name + "[" + std::to_string(k) + "]", width).transpose();
  }
  return out;
}

Eigen::VectorXd times(const nlohmann::json& value, double T) {
  if (!value.is_array() || value.size() < 2) bad("t", describe(value), "must be a list of at least 2 times");
  const Eigen::VectorXd t = numbers(value, "t", value.size());
  for (Eigen::Index k = 1; k < t.size(); ++k) {
    if (!(t[k] > t[k - 1])) {
      bad("t[" + std::to_string(k) + "]", format_value(t[k]),
          "is not greater than t[" + std::to_string(k - 1) + "] = " + format_value(t[k - 1]) + " (times must increase)");
    }
  }
  if (std::abs(t[0]) > kTimeSpanTolerance * T) bad("t[0]", format_value(t[0]), "must be 0");
  if (std::abs(t[t.size() - 1] - T) > kTimeSpanTolerance * T) {
    bad("t[" + std::to_string(t.size() - 1) + "]", format_value(t[t.size() - 1]), "must equal T = " + format_value(T));
  }
  return t;
}

ResultFile read(const nlohmann::json& j) {
  if (!j.is_object()) bad("result file", describe(j), "must be a JSON object");
  ResultFile r;
  r.status = one_of(require_key(j, "status"), "status", enum_words<Status>());
  r.group = one_of(require_key(j, "group"), "group", {"so3", "heisenberg"});
  const bool so3 = r.group == "so3";
  r.model = one_of(require_key(j, "model"), "model",
                   so3 ? std::vector<std::string>{"free-rigid-body", "oscillator"} : std::vector<std::string>{"oscillator"});
  r.method = one_of(require_key(j, "method"), "method", enum_words<transported::Method>());
  r.order = integer(require_key(j, "order"), "order");
  if (r.order != 1 && r.order != 2 && r.order != 4) bad("order", std::to_string(r.order), "must be 1, 2 or 4");
  r.lambda = finite_number(require_key(j, "lambda"), "lambda");
  r.T = positive_number(require_key(j, "T"), "T");
  r.N = integer(require_key(j, "N"), "N");
  if (r.N < 1) bad("N", std::to_string(r.N), "must be at least 1");
  r.tol = positive_number(require_key(j, "tol"), "tol");
  r.inertia = numbers(require_key(j, "inertia"), "inertia", 3);
  for (int i = 0; i < 3; ++i) {
    if (!(r.inertia[i] > 0)) bad("inertia", format_value(r.inertia.transpose()), "is not positive definite (entries must be > 0)");
  }
  const std::size_t width = so3 ? 9 : 3;
  r.g0 = numbers(require_key(j, "g0"), "g0", width);
  r.gT = numbers(require_key(j, "gT"), "gT", width);
  if (so3) require_rotation(r.g0, "g0"), require_rotation(r.gT, "gT");
  r.t = times(require_key(j, "t"), r.T);
  const auto rows = static_cast<std::size_t>(r.t.size());
  r.g = table(require_key(j, "g"), "g", rows, width);
  if (so3) {
    for (Eigen::Index k = 0; k < r.g.rows(); ++k) require_rotation(r.g.row(k).transpose(), "g[" + std::to_string(k) + "]");
  }
  r.v = table(require_key(j, "v"), "v", rows, 3);
  r.mu = table(require_key(j, "mu"), "mu", rows, 3);
  r.xi = table(require_key(j, "xi"), "xi", rows, 3);
  return r;
}

}  // namespace

ResultFile read_result(const nlohmann::json& j) {
  try {
    return read(j);
  } catch (const nlohmann::json::exception& e) {  // unreachable by the checks above; kept as a guarantee
    throw std::invalid_argument(std::string(kWhere) + ": result file: " + e.what());
  }
}

}  // namespace cartan::cli
