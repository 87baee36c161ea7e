#pragma once
// The one check of a sampled trajectory, for both kernels and every use of one (a guess, a
// trajectory to verify, the quantities along a solution): one entry per time in every column, at
// least `min_times` times, the times strictly increasing from 0 to T (require_sample_times), and,
// where asked, every entry finite. One wording, "<where>: <name> = <value> <problem>":
//   <what>.t.size() = 1 must be at least 2
//   <what> = (5 times) needs g, v, mu and xi at every time
//   <what>.v (row 3) = [nan 0 0] must be finite

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cartan/errors.hpp"

namespace cartan {

/// One column of a sampled trajectory as require_samples sees it: its name, its number of rows
/// and its first row that is not finite (with that row written out), where there is one.
struct SampleColumn {
  std::string_view name;
  std::size_t rows = 0;
  std::optional<std::size_t> nonfinite_row;
  std::string nonfinite_value;
};

/// The column `name` of entries `rows` (Eigen vectors or matrices).
template <class Row>
SampleColumn sample_column(std::string_view name, const std::vector<Row>& rows) {
  SampleColumn column{name, rows.size(), std::nullopt, {}};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (!rows[k].allFinite()) {
      column.nonfinite_row = k;
      column.nonfinite_value = format_value(rows[k]);
      break;
    }
  }
  return column;
}

/// What require_samples asks of the samples besides one entry per time in every column.
struct SampleRules {
  std::size_t min_times = 2;
  /// The times strictly increase from 0 to T within time_tolerance * T (where there are at least 2).
  bool check_times = true;
  double time_tolerance = 1e-12;
  /// Every entry (times included) finite; else require_samples only says whether they are.
  bool require_finite = true;
};

/// Throws std::invalid_argument (the header's wording) unless the samples at times `t` with
/// `columns` keep `rules` on the horizon [0, T]; returns whether every entry (times included) is
/// finite, which is always so when rules.require_finite.
bool require_samples(const std::vector<double>& t, double T, std::initializer_list<SampleColumn> columns,
                     const SampleRules& rules, std::string_view where, std::string_view what);

}  // namespace cartan
