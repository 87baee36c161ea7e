// Built against an installed cartan: find_package(cartan) + cartan::cartan must be enough.
#include <cartan/connections/cartan_schouten.hpp>
#include <cartan/groups/so3.hpp>
#include <cstdio>

int main() {
  const Eigen::Vector3d u(1, 0, 0), v(0, 1, 0), w(0, 0, 1);
  const auto conn = cartan::connections::cartan_schouten<cartan::groups::SO3>(0.5);
  const Eigen::Vector3d r = conn.curvature(u, v, w);  // -1/4 [[u,v],w] = 0 here; use [[u,v],u]
  const Eigen::Vector3d r2 = conn.curvature(u, v, u);  // -1/4 (e3 x e1) = -1/4 e2
  const double angle = cartan::groups::SO3::log(cartan::groups::SO3::exp(Eigen::Vector3d(0.1, 0.2, 0.3))).norm();
  std::printf("%.6f %.6f %.6f\n", r.norm(), r2.y(), angle);
  return (r.norm() < 1e-15 && r2.y() == -0.25 && angle > 0.374 && angle < 0.375) ? 0 : 1;
}
