// A tour of cartan's core geometry, printed as numbers: run by `make run`.
#include <cstdio>
#include <numbers>

#include "cartan/groups/heisenberg.hpp"
#include "cartan/groups/so3.hpp"

int main() {
  using namespace cartan;
  const Eigen::Vector3d a0 = Eigen::Vector3d(-1, -1, -1).normalized();
  const Eigen::Vector3d aT = Eigen::Vector3d(0.9, 1.0, 1.0).normalized();
  const Eigen::Matrix3d gT = groups::SO3::minimal_rotation(a0, aT);
  const Eigen::Vector3d w = groups::SO3::log(gT);
  std::printf("SO(3): minimal rotation a0 -> aT (paper's free-body endpoints)\n");
  std::printf("  log(gT) = (%.15f, %.15f, %.15f), angle %.15f rad\n", w.x(), w.y(), w.z(), w.norm());
  const double gap = 1e-7;
  const Eigen::Vector3d near_pi = Eigen::Vector3d(1, 2, 2).normalized() * (std::numbers::pi - gap);
  std::printf("  log(exp(v)) near pi (|v| = pi - 1e-7): relative error %.3e\n",
              (groups::SO3::log(groups::SO3::exp(near_pi)) - near_pi).norm() / near_pi.norm());
  const Eigen::Vector3d g(1.0, 0.5, 0.8);
  const Eigen::Vector3d v = groups::Heisenberg::log(g);
  std::printf("H3: log(1, 0.5, 0.8) = (%.15f, %.15f, %.15f); exp(log g) - g = %.3e\n", v[0], v[1], v[2],
              (groups::Heisenberg::exp(v) - g).norm());
  return 0;
}
