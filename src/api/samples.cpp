// The one check of samples' tables (samples.hpp).
#include "samples.hpp"

#include <string>

#include "cartan/errors.hpp"

namespace cartan::api::detail {

void check_samples(const Samples& x, Eigen::Index point_size, Eigen::Index n, Eigen::Index aux_width, std::string_view where,
                   Eigen::Index frame_size) {
  const Eigen::Index m = x.t.size();
  const auto require = [&](const Eigen::MatrixXd& table, const char* name, Eigen::Index width) {
    if (table.rows() == m && (table.cols() == width || m == 0)) return;  // no samples: tables of any width
    throw_invalid(where, std::string("samples.") + name, "(" + std::to_string(table.rows()) + " x " + std::to_string(table.cols()) + " numbers)",
                  "must have " + std::to_string(m) + " rows (one per time) of " + std::to_string(width) + " numbers");
  };
  require(x.points, "points", point_size);
  if (frame_size > 0) require(x.frames, "frames", frame_size);
  require(x.v, "v", n);
  require(x.mu, "mu", n);
  require(x.aux, "aux", aux_width);
}

}  // namespace cartan::api::detail
