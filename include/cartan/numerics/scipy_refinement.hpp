#pragma once
// The mesh refinement rule of scipy.integrate.solve_bvp (SciPy 1.10, Kierzenka & Shampine 2001),
// for cartan.solve_bvp (python/cartan/_bvp.py), which reproduces SciPy's node counts: an interval
// whose RMS residual r satisfies tol < r < 100 tol gets one node in its middle, one with
// r >= 100 tol two nodes at its thirds; the next mesh's guess is the cubic interpolant there.
// (cartan's own solver splits by the O(h^3) residual model instead: numerics/collocation.hpp.)
// Comparisons are SciPy's, NaN included: a NaN residual or tol adds no node.

#include <Eigen/Core>
#include <vector>

#include "cartan/errors.hpp"
#include "cartan/numerics/cubic_hermite.hpp"

namespace cartan::numerics {

struct RefinedMesh {
  Eigen::VectorXd t;  ///< the next mesh (the old nodes and the inserted ones, increasing)
  Eigen::MatrixXd y;  ///< the interpolant at t (exactly the old values at the old nodes)
  int added = 0;      ///< nodes inserted
};

/// The next mesh of `solution` (m nodes) by SciPy's rule, from the m - 1 interval residuals `rms`.
/// Throws std::invalid_argument when rms does not have one entry per interval.
inline RefinedMesh scipy_refinement(const CubicHermite& solution, const Eigen::VectorXd& rms, double tol) {
  const Eigen::VectorXd& t = solution.nodes();
  const Eigen::MatrixXd& y = solution.node_values();
  const Eigen::Index intervals = t.size() - 1;
  if (rms.size() != intervals) {
    throw_invalid("scipy_refinement", "rms.size()", std::to_string(rms.size()),
                  "must equal the number of intervals, " + std::to_string(intervals));
  }
  std::vector<int> inserted(static_cast<std::size_t>(intervals), 0);
  int added = 0;
  for (Eigen::Index i = 0; i < intervals; ++i) {
    const int count = rms[i] >= 100 * tol ? 2 : rms[i] > tol ? 1 : 0;  // NaN compares false: 0
    inserted[static_cast<std::size_t>(i)] = count;
    added += count;
  }
  RefinedMesh out{Eigen::VectorXd(t.size() + added), Eigen::MatrixXd(y.rows(), t.size() + added), added};
  Eigen::Index j = 0;
  auto push = [&](double time, const Eigen::VectorXd& value) {
    out.t[j] = time;
    out.y.col(j++) = value;
  };
  for (Eigen::Index i = 0; i < intervals; ++i) {
    push(t[i], y.col(i));
    // SciPy's modify_mesh: the middle, or the thirds (2 a + b) / 3 and (a + 2 b) / 3.
    if (inserted[static_cast<std::size_t>(i)] == 1) {
      const double middle = 0.5 * (t[i] + t[i + 1]);
      push(middle, solution.value_on(i, middle));
    } else if (inserted[static_cast<std::size_t>(i)] == 2) {
      const double first = (2 * t[i] + t[i + 1]) / 3, second = (t[i] + 2 * t[i + 1]) / 3;
      push(first, solution.value_on(i, first));
      push(second, solution.value_on(i, second));
    }
  }
  push(t[intervals], y.col(intervals));
  return out;
}

}  // namespace cartan::numerics
