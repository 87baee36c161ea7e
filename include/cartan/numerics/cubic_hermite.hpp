#pragma once
// The C^1 piecewise-cubic Hermite interpolant through (t_i, y_i) with slopes y'_i: the dense
// output of the collocation solver (numerics/collocation.hpp). On [t_i, t_i + h], with s = (t - t_i)/h,
//   S(t) = H00(s) y_i + h H10(s) y'_i + H01(s) y_{i+1} + h H11(s) y'_{i+1},
// H00 = (1 + 2s)(1 - s)^2, H10 = s (1 - s)^2, H01 = s^2 (3 - 2s), H11 = s^2 (s - 1).
// Outside [t_0, t_{m-1}] the first or last cubic is extended.

#include <Eigen/Core>
#include <algorithm>
#include <utility>

namespace cartan::numerics {

class CubicHermite {
 public:
  CubicHermite() = default;
  /// t: m strictly increasing nodes (m >= 2); y, yp: n x m values and slopes.
  CubicHermite(Eigen::VectorXd t, Eigen::MatrixXd y, Eigen::MatrixXd yp)
      : t_(std::move(t)), y_(std::move(y)), yp_(std::move(yp)) {}

  Eigen::VectorXd value(double t) const {
    Eigen::VectorXd out(y_.rows());
    evaluate(t, &out, nullptr);
    return out;
  }

  Eigen::VectorXd derivative(double t) const {
    Eigen::VectorXd out(y_.rows());
    evaluate(t, nullptr, &out);
    return out;
  }

  /// S(t) and/or S'(t) into preallocated vectors of size n (either may be null).
  void evaluate(double t, Eigen::VectorXd* value, Eigen::VectorXd* derivative) const {
    evaluate_at(locate(t), value, derivative);
  }
  /// S(t) by the cubic of interval i ([t_i, t_{i+1}], extended beyond it), without searching for
  /// the interval (i in [0, m - 2]).
  Eigen::VectorXd value_on(Eigen::Index i, double t) const {
    Eigen::VectorXd out(y_.rows());
    const double h = t_[i + 1] - t_[i];
    evaluate_at({i, (t - t_[i]) / h, h}, &out, nullptr);
    return out;
  }

  /// Values at several times, one column per time.
  Eigen::MatrixXd values(const Eigen::VectorXd& times) const {
    Eigen::MatrixXd out(y_.rows(), times.size());
    for (Eigen::Index j = 0; j < times.size(); ++j) out.col(j) = value(times[j]);
    return out;
  }

  const Eigen::VectorXd& nodes() const { return t_; }
  const Eigen::MatrixXd& node_values() const { return y_; }

 private:
  struct Place {
    Eigen::Index interval;
    double s, h;
  };
  void evaluate_at(const Place& place, Eigen::VectorXd* value, Eigen::VectorXd* derivative) const {
    const auto [i, s, h] = place;
    if (value) {
      const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
      const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
      value->noalias() = h00 * y_.col(i) + h * h10 * yp_.col(i) + h01 * y_.col(i + 1) + h * h11 * yp_.col(i + 1);
    }
    if (derivative) {
      const double d00 = 6 * s * (s - 1), d10 = (1 - s) * (1 - 3 * s);
      const double d01 = -d00, d11 = s * (3 * s - 2);
      derivative->noalias() = (d00 * y_.col(i) + d01 * y_.col(i + 1)) / h + d10 * yp_.col(i) + d11 * yp_.col(i + 1);
    }
  }

  Place locate(double t) const {
    const Eigen::Index m = t_.size();
    const auto* begin = t_.data();
    const Eigen::Index upper = std::upper_bound(begin, begin + m, t) - begin;
    const Eigen::Index i = std::clamp<Eigen::Index>(upper - 1, 0, m - 2);
    const double h = t_[i + 1] - t_[i];
    return {i, (t - t_[i]) / h, h};
  }

  Eigen::VectorXd t_;
  Eigen::MatrixXd y_, yp_;
};

}  // namespace cartan::numerics
