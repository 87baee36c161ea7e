#pragma once
// What collocation of every kernel shares (transported/collocation_solution.hpp,
// general/collocation.hpp): where a result is sampled.

#include <Eigen/Core>

#include "cartan/numerics/collocation.hpp"
#include "cartan/principle/options.hpp"

namespace cartan::solvers {

/// Output times: the final mesh (samples == 0) or `samples` uniform times on [0, T].
inline Eigen::VectorXd output_times(const numerics::BvpResult& result, int samples, double T) {
  return samples == 0 ? result.t : Eigen::VectorXd::LinSpaced(samples, 0, T);
}

}  // namespace cartan::solvers
