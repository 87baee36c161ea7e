// The one check of samples' tables (samples.hpp).
#include "samples.hpp"

#include <string>

#include "cartan/errors.hpp"

namespace cartan::api::detail {

void check_table(const Samples& x, const Table& table, const char* name, Eigen::Index width, std::string_view where,
                 bool optional) {
  const Eigen::Index m = x.t.size();
  // No samples: tables without rows, of any width (a failed result's empty arrays).
  if ((table.rows() == m && (table.cols() == width || m == 0)) || (optional && table.rows() == 0)) return;
  throw_invalid(where, std::string("samples.") + name, "(" + std::to_string(table.rows()) + " x " + std::to_string(table.cols()) + " numbers)",
                "must have " + std::to_string(m) + " rows (one per time) of " + std::to_string(width) + " numbers");
}

void check_samples(const Samples& x, Eigen::Index point_size, Eigen::Index n, Eigen::Index aux_width, std::string_view where,
                   Eigen::Index frame_size) {
  check_table(x, x.points, "points", point_size, where);
  if (frame_size > 0) check_table(x, x.frames, "frames", frame_size, where);
  check_table(x, x.v, "v", n, where);
  check_table(x, x.mu, "mu", n, where);
  check_table(x, x.aux, "aux", aux_width, where);
}

}  // namespace cartan::api::detail
