// The instances of manifold_instances.hpp whose callbacks the solvers call at every step, compiled
// once with the library's optimisation (the suites that use them may be compiled at -O0).
#include "manifolds/manifold_instances.hpp"

namespace cartan::testing {

VaryingChart::Manifold VaryingChart::make() {
  std::mt19937 rng(kSeed + 2);
  Manifold::Coefficients a, b;
  for (auto& g : a) g = random_vector<Eigen::Matrix<double, 4, 1>>(rng, 0.5).reshaped(2, 2);
  for (auto& g : b) g = random_vector<Eigen::Matrix<double, 4, 1>>(rng, 0.5).reshaped(2, 2);
  const Eigen::Vector2d c(0.7, -0.4);
  return Manifold([a, b, c](const Eigen::Vector2d& q) {
    Manifold::Coefficients g;
    for (int i = 0; i < 2; ++i) g[i] = a[i] + q.dot(c) * b[i];
    return g;
  });
}

}  // namespace cartan::testing
