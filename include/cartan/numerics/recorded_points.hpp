#pragma once
// The trajectories of the last points a shooting solve evaluated, in two buffers, so that its
// result - the best point, which Levenberg–Marquardt accepts only with a smaller |r| - has its
// trajectory at hand without another sweep, even when a stop (time limit, cancellation) cut the
// last sweep short: a sweep never records into the buffer that holds the best point so far.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <limits>

namespace cartan::numerics {

template <class Trajectory>
class RecordedPoints {
 public:
  /// The buffer for a sweep at x; it holds no point until `finish`.
  Trajectory* start(const Eigen::VectorXd& x) {
    writing_ = 1 - best();
    Slot& slot = slots_[writing_];
    slot.x.resize(0);
    slot.pending = x;
    return &slot.trajectory;
  }
  /// The sweep begun by the last `start` completed, with residual norm `norm`.
  void finish(double norm) {
    Slot& slot = slots_[writing_];
    slot.x = slot.pending;
    slot.norm = norm;
  }
  /// The recorded trajectory of the point x, or null.
  Trajectory* find(const Eigen::VectorXd& x) {
    for (Slot& slot : slots_) {
      if (slot.x.size() == x.size() && slot.x == x) return &slot.trajectory;
    }
    return nullptr;
  }

 private:
  struct Slot {
    Trajectory trajectory;
    Eigen::VectorXd x, pending;  ///< x: the point recorded (empty: none)
    double norm = std::numeric_limits<double>::infinity();
  };
  bool holds(std::size_t i) const { return slots_[i].x.size() > 0; }
  /// The slot with the smaller |r| among those holding a point (1 when neither does).
  std::size_t best() const { return holds(0) && (!holds(1) || slots_[0].norm <= slots_[1].norm) ? 0 : 1; }
  std::array<Slot, 2> slots_;
  std::size_t writing_ = 0;
};

}  // namespace cartan::numerics
