// What a manifold's result carries along it (kernels/manifold/along.hpp) and the check of a manifold's
// Lagrangian (mechanics/manifold_check_lagrangian.hpp), against closed forms on the sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "cartan/kernels/manifold/along.hpp"
#include "cartan/mechanics/manifold_check_lagrangian.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

using manifolds::Sphere;

// A great circle travelled at constant speed w, sampled at uneven times: the frame transported
// along the sphere's pieces (great-circle arcs) is the closed-form parallel frame, u = E v is the
// tangent q', l = 1/2 |v|^2 gives E = 1/2 w^2 at every node and, the midpoint rule being exact for
// a constant integrand, S = 1/2 w^2 t_k over the first k steps. Rounding only (1e-14).
TEST(GeneralAlong, ClosedFormsOnAGreatCircle) {
  const Eigen::Vector3d q0(1, 0, 0), e1(0, 0.6, 0.8), e2 = q0.cross(e1);
  const double w = std::numbers::pi / 3, T = 1.5;
  const auto point = [&](double t) -> Eigen::Vector3d { return std::cos(w * t) * q0 + std::sin(w * t) * e1; };
  const auto frame = [&](double t) {
    Sphere::Frame e;
    e.col(0) = -std::sin(w * t) * q0 + std::cos(w * t) * e1;
    e.col(1) = e2;
    return e;
  };
  general::GeneralTrajectory<Sphere> x;
  for (double t : {0.0, 0.2, 0.5, 0.6, 0.9, 1.2, T}) {
    x.t.push_back(t), x.q.push_back(point(t)), x.v.push_back(Eigen::Vector2d(w, 0));
  }
  const general::ErasedProblem<Sphere> problem{
      Sphere{}, general::ErasedLagrangian<Sphere>(general::KineticPotential<Sphere>(Eigen::Matrix2d::Identity())), T, 6,
      point(0), point(T), frame(0)};
  const general::GeneralAlong<Sphere> along = general::along_general(problem, x);
  ASSERT_EQ(along.frame.size(), x.t.size());
  for (std::size_t k = 0; k < x.t.size(); ++k) {
    EXPECT_NEAR_MATRIX(along.frame[k], frame(x.t[k]), 1e-14);
    EXPECT_NEAR_MATRIX(along.u[k], Eigen::Vector3d(w * frame(x.t[k]).col(0)), 1e-14);
    EXPECT_NEAR(along.energy[k], 0.5 * w * w, 1e-14);
    EXPECT_NEAR(along.action[k], 0.5 * w * w * x.t[k], 1e-14);
  }
  EXPECT_EQ(along.action.front(), 0.0);
  general::GeneralTrajectory<Sphere> short_t = x;
  short_t.t.back() = 1.4;  // does not reach T
  expect_invalid([&] { general::along_general(problem, short_t); }, {"along_general", "must run from 0 to T = 1.5"});
  short_t.v.pop_back();
  expect_invalid([&] { general::along_general(problem, short_t); }, {"along_general", "needs q and v at every time"});
}

/// l = 1/2 v.A v - G q_3 on the sphere, its point gradient changed as `Wrong` says.
enum class Wrong { None, Sign, Normal };
struct Pendulum {
  Wrong wrong = Wrong::None;
  general::KineticPotential<Sphere> l{Eigen::Vector2d(1, 2.5).asDiagonal(),
                                      [](const Eigen::Vector3d& q) { return 9.81 * q.z(); },
                                      [](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, 9.81); }};
  double value(double t, const Eigen::Vector3d& q, const Eigen::Vector2d& v) const { return l.value(t, q, v); }
  Eigen::Vector2d momentum(double t, const Eigen::Vector3d& q, const Eigen::Vector2d& v) const { return l.momentum(t, q, v); }
  Eigen::Vector2d velocity(double t, const Eigen::Vector3d& q, const Eigen::Vector2d& mu) const { return l.velocity(t, q, mu); }
  Eigen::Vector3d point_gradient(double t, const Eigen::Vector3d& q, const Eigen::Vector2d& v) const {
    const Eigen::Vector3d zeta = l.point_gradient(t, q, v);
    return wrong == Wrong::Sign ? Eigen::Vector3d(-zeta) : wrong == Wrong::Normal ? Eigen::Vector3d(zeta + 3 * q) : zeta;
  }
};

// A problem without frame0 whose endpoints leave the sphere's default frame undefined (equal or
// antipodal: tangent_basis(q0) is then a convention) is the same problem in every orthonormal frame
// only if its Lagrangian does not see the frame: refused otherwise, the kernel's own rule, so that
// every door (api, Python, a C++ caller) refuses the same problems.
struct OwnKinetic {  // a Lagrangian of the user's: 1/2 v.v, but it does not say that it is frame invariant
  double value(double, const Eigen::Vector3d&, const Eigen::Vector2d& v) const { return 0.5 * v.squaredNorm(); }
  Eigen::Vector2d momentum(double, const Eigen::Vector3d&, const Eigen::Vector2d& v) const { return v; }
  Eigen::Vector2d velocity(double, const Eigen::Vector3d&, const Eigen::Vector2d& mu) const { return mu; }
  Eigen::Vector3d point_gradient(double, const Eigen::Vector3d&, const Eigen::Vector2d&) const { return Eigen::Vector3d::Zero(); }
};

TEST(GeneralProblem, RefusesTheFallbackFrameWhereTheLagrangianDependsOnIt) {
  using Particle = general::KineticPotential<Sphere>;
  const Eigen::Vector3d q0(0, 0, 1);
  const Particle isotropic(2 * Eigen::Matrix2d::Identity()), anisotropic(Eigen::Vector2d(1, 2).asDiagonal());
  EXPECT_TRUE(mechanics::frame_invariant_of(isotropic));
  EXPECT_FALSE(mechanics::frame_invariant_of(anisotropic));
  EXPECT_FALSE(mechanics::frame_invariant_of(OwnKinetic{}));
  EXPECT_TRUE(mechanics::frame_invariant_of(general::ErasedLagrangian<Sphere>(isotropic)));  // carried through the erasure
  EXPECT_FALSE(mechanics::frame_invariant_of(general::ErasedLagrangian<Sphere>(anisotropic)));
  for (const Eigen::Vector3d& qT : {q0, Eigen::Vector3d(-q0)}) {
    const auto posed = [&](const Particle& l, std::optional<Sphere::Frame> frame0) {
      return general::ErasedProblem<Sphere>{Sphere{}, general::ErasedLagrangian<Sphere>(l), 1, 10, q0, qT, frame0};
    };
    EXPECT_NO_THROW(posed(isotropic, std::nullopt).validate());
    expect_invalid([&] { posed(anisotropic, std::nullopt).validate(); },
                   {"GeneralProblem: q0/qT = [0, 0, 1]", qT == q0 ? "are equal" : "are antipodal", "give frame0"});
    expect_invalid([&] { general::GeneralProblem<Sphere, OwnKinetic>{Sphere{}, {}, 1, 10, q0, qT, std::nullopt}.validate(); },
                   {"give frame0"});
    EXPECT_NO_THROW(posed(anisotropic, Sphere::tangent_basis(q0)).validate());
  }
  // Where the frame towards qT is defined, the default frame is that one for every Lagrangian.
  EXPECT_NO_THROW((general::GeneralProblem<Sphere, OwnKinetic>{Sphere{}, {}, 1, 10, q0, Eigen::Vector3d(1, 0, 0), std::nullopt}.validate()));
}

// The manifold's check names a wrong point gradient (a sign: O(1)) and ignores what is not defined
// of it (a normal part on the sphere); a correct Lagrangian agrees to the differences' accuracy
// (mechanics/manifold_check_lagrangian.hpp: 1e-10; asserted 1e-8).
TEST(GeneralCheckLagrangian, NamesAWrongPointGradientOnly) {
  const Sphere sphere;
  mechanics::CheckLagrangianOptions options;
  const auto samples = general::lagrangian_samples(sphere, Eigen::Vector3d(0, 0, 1), options);
  ASSERT_EQ(samples.size(), 8u);
  for (const auto& s : samples) EXPECT_NEAR(s.q.norm(), 1.0, 1e-15);
  for (Wrong wrong : {Wrong::None, Wrong::Normal}) {
    const auto report = general::check_lagrangian(sphere, Pendulum{wrong}, samples);
    EXPECT_TRUE(report.ok()) << report.text();
    for (const auto& c : report.checks) EXPECT_LE(c.discrepancy, 1e-8) << c.callback;
  }
  const auto report = general::check_lagrangian(sphere, Pendulum{Wrong::Sign}, samples);
  EXPECT_EQ(report.failing(), std::vector<std::string>{"point_gradient"}) << report.text();
  expect_invalid([&] { general::lagrangian_samples(sphere, Eigen::Vector3d(0, 0, 2), options); }, {"check_lagrangian", "unit sphere"});
  expect_invalid([&] { general::check_lagrangian(sphere, Pendulum{}, {}); }, {"samples", "must not be empty"});
}

}  // namespace
}  // namespace cartan::testing
