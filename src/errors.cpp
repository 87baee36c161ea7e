#include "cartan/errors.hpp"

#include <charconv>
#include <cmath>
#include <limits>

namespace cartan {

std::string format_value(double x) {
  char buffer[32];  // the shortest round trip of a double has at most 24 characters
  const std::to_chars_result end = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, end.ptr);
}

namespace {
/// A matrix of more entries than a group's 4 x 4 element is cut after this many characters, "...]"
/// (about 8 numbers): a message names a value, and 10^4 entries of a collocation guess flooded it
/// (18 KB).
constexpr Eigen::Index kWholeEntries = 16;
constexpr std::size_t kMaxValueCharacters = 160;
}  // namespace

std::string format_value(const Eigen::Ref<const Eigen::MatrixXd>& x) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    if (i > 0) out += "; ";
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      if (x.size() > kWholeEntries && out.size() > kMaxValueCharacters) return out + "...]";
      if (j > 0) out += ", ";
      out += format_value(x(i, j));
    }
  }
  return out + ']';
}

std::string quote_input(std::string_view text) {
  constexpr std::size_t kMaxShown = 60;
  std::string out = "\"";
  for (std::size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
      out += static_cast<char>(c);
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xf];
    }
  }
  out += text.size() > kMaxShown ? "\"..." : "\"";
  return out;
}

void throw_invalid(std::string_view where, std::string_view name, const std::string& value,
                   std::string_view problem) {
  std::ostringstream out;
  out << where << ": " << name << " = " << value << ' ' << problem;
  throw std::invalid_argument(out.str());
}

void require_finite(const Eigen::Ref<const Eigen::MatrixXd>& x, std::string_view where,
                    std::string_view name) {
  if (!x.allFinite()) throw_invalid(where, name, format_value(x), "contains a non-finite number");
}

void require_finite(double x, std::string_view where, std::string_view name) {
  if (!std::isfinite(x)) throw_invalid(where, name, format_value(x), "is not finite");
}

void require_reachable_tolerance(double tol, std::string_view where, std::string_view name) {
  if (!(tol > 0)) throw_invalid(where, name, format_value(tol), "must be positive");
  constexpr double kFloor = 100 * std::numeric_limits<double>::epsilon();
  if (tol < kFloor) {
    throw_invalid(where, name, format_value(tol),
                  "is below 100 machine epsilons (" + format_value(kFloor) + "): no method can reach it");
  }
}

void require_shape(const Eigen::Ref<const Eigen::MatrixXd>& x, Eigen::Index rows, Eigen::Index cols,
                   std::string_view where, std::string_view name) {
  if (x.rows() != rows || x.cols() != cols) {
    std::ostringstream shape;
    shape << "has shape " << x.rows() << "x" << x.cols() << ", expected " << rows << "x" << cols;
    throw_invalid(where, name, format_value(x), shape.str());
  }
}

std::string excerpt(const std::vector<double>& values) {
  constexpr std::size_t kMaxShown = 60;
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ',';
    out += format_value(values[i]);
    if (out.size() > kMaxShown) return out.substr(0, kMaxShown) + "... (" + std::to_string(values.size()) + " numbers)";
  }
  return out;
}

}  // namespace cartan
