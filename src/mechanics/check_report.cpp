#include "cartan/mechanics/check_report.hpp"

#include <cstdio>

namespace cartan::mechanics {

namespace {

std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2e", x);
  return buffer;
}

}  // namespace

bool CheckReport::ok() const {
  for (const auto& c : checks) {
    if (!c.ok) return false;
  }
  return true;
}

std::vector<std::string> CheckReport::failing() const {
  std::vector<std::string> out;
  for (const auto& c : checks) {
    if (!c.ok) out.push_back(c.callback);
  }
  return out;
}

std::string CheckReport::text() const {
  std::string failed;
  for (const auto& name : failing()) failed += (failed.empty() ? "" : ", ") + name;
  std::string out = title + ": " + (ok() ? std::string("PASS") : "FAIL (" + failed + ")") + ", " +
                    std::to_string(samples) + " samples\n";
  for (const auto& c : checks) {
    out += "  " + c.callback + ": ";
    if (!c.checked) {
      out += "- (" + c.note + ")\n";
      continue;
    }
    out += std::string(c.ok ? "PASS" : "FAIL") + ", relative discrepancy " + short_number(c.discrepancy) +
           " (reference error " + short_number(c.reference_error) + ", threshold " + short_number(c.threshold) +
           ") against " + c.reference;
    if (!c.note.empty()) out += "; " + c.note;
    if (!c.ok && c.sample >= 0) out += "; at sample " + std::to_string(c.sample) + ": " + c.at;
    out += "\n";
  }
  return out;
}

}  // namespace cartan::mechanics
