// The one check of a sampled trajectory (cartan/principle/samples.hpp).
#include "cartan/principle/samples.hpp"

#include <cmath>

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

}  // namespace

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
