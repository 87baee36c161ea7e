#pragma once
// The paper's SO(3) problems (§7 "Numerical examples") as TransportedProblems.

#include <cmath>

#include "cartan/mechanics/rigid_body.hpp"
#include "cartan/principle/group_problem.hpp"

namespace cartan::testing {

inline Eigen::Matrix3d paper_inertia() { return Eigen::Vector3d(2, 3, 4).asDiagonal(); }

inline transported::TransportedProblem<groups::SO3, mechanics::RigidBody> paper_free_body(double lambda, int N = 1000, double T = 50) {
  const Eigen::Vector3d a0 = Eigen::Vector3d(-1, -1, -1) / std::sqrt(3.0);
  const Eigen::Vector3d aT = Eigen::Vector3d(0.9, 1.0, 1.0) / std::sqrt(2.81);
  return {mechanics::RigidBody(paper_inertia()), lambda, T, N, groups::SO3::identity(), groups::SO3::minimal_rotation(a0, aT)};
}

inline transported::TransportedProblem<groups::SO3, mechanics::SO3Oscillator> paper_oscillator(double lambda, int N = 800, double T = 12) {
  const Eigen::Vector3d a0 = Eigen::Vector3d(-0.7, -1.0, -0.7) / std::sqrt(1.98);
  const Eigen::Vector3d aT = Eigen::Vector3d(0.8, 0.8, 1.0) / std::sqrt(2.28);
  return {mechanics::SO3Oscillator(paper_inertia()), lambda, T, N, groups::SO3::identity(), groups::SO3::minimal_rotation(a0, aT)};
}

}  // namespace cartan::testing
