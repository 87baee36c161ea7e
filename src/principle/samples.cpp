// The one check of a sampled trajectory (cartan/principle/samples.hpp), and the check that a
// horizon's steps fit in memory (cartan/principle/horizon.hpp).
#include "cartan/principle/samples.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "cartan/principle/horizon.hpp"

namespace cartan {

namespace {

/// "g, v, mu and xi".
std::string listed(std::initializer_list<SampleColumn> columns) {
  std::string out;
  std::size_t k = 0;
  for (const SampleColumn& c : columns) {
    if (k > 0) out.append(k + 1 == columns.size() ? " and " : ", ");
    out.append(c.name);
    ++k;
  }
  return out;
}

/// This machine's physical memory in bytes (0 where the system does not say).
double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

}  // namespace

void require_steps_fit(int N, std::string_view where) {
  static const double memory = physical_memory();
  const double bytes = kBytesPerStepAtLeast * N;
  if (memory > 0 && bytes > memory) {
    char text[96];
    std::snprintf(text, sizeof text, "needs at least %.3g GiB (%g KiB per step), more than this machine's %.3g GiB",
                  bytes / (1 << 30), kBytesPerStepAtLeast / 1024, memory / (1 << 30));
    throw_invalid(where, "N", std::to_string(N), text);
  }
}

bool require_samples(const std::vector<double>& t, double T, std::initializer_list<SampleColumn> columns,
                     const SampleRules& rules, std::string_view where, std::string_view what) {
  const std::size_t n = t.size();
  if (n < rules.min_times) {
    throw_invalid(where, std::string(what).append(".t.size()"), std::to_string(n),
                  std::string("must be at least ").append(std::to_string(rules.min_times)));
  }
  for (const SampleColumn& c : columns) {
    if (c.rows != n) {
      throw_invalid(where, what, std::string("(").append(std::to_string(n)).append(" times)"),
                    std::string("needs ").append(listed(columns)).append(" at every time"));
    }
  }
  bool finite = true;
  for (std::size_t k = 0; k < n && finite; ++k) finite = std::isfinite(t[k]);
  for (const SampleColumn& c : columns) {
    if (!c.nonfinite_row) continue;
    finite = false;
    if (rules.require_finite) {
      throw_invalid(where,
                    std::string(what).append(".").append(c.name).append(" (row ")
                        .append(std::to_string(*c.nonfinite_row)).append(")"),
                    c.nonfinite_value, "must be finite");
    }
  }
  if (rules.check_times && n >= 2) require_sample_times(t, T, rules.time_tolerance, where, what);
  return finite;
}

}  // namespace cartan
