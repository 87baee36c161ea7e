// check_lagrangian (mechanics/check_lagrangian.hpp): every built-in model passes; models with
// one deliberate defect fail exactly the check of the defective callback, with the size of the
// defect as the discrepancy; scale does not fool it; non-finite values and exceptions are reported.
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cartan/mechanics/check_lagrangian.hpp"
#include "cartan/mechanics/free_body.hpp"
#include "cartan/mechanics/heisenberg_oscillator.hpp"
#include "cartan/mechanics/rigid_body.hpp"
#include "test_support.hpp"

namespace cartan::testing {
namespace {

using mechanics::CheckLagrangianOptions;
using mechanics::CheckReport;
using mechanics::check_lagrangian;
using groups::SO3;

// A correct derivative agrees with central differences to ~1e-10 relative (the header's error
// analysis); 1e-8 leaves a factor 100 for the models' larger third derivatives.
constexpr double kPassing = 1e-8;

Eigen::Matrix3d inertia3() { return (Eigen::Matrix3d() << 2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.0).finished(); }

void expect_passes(const CheckReport& report, int analytic_hessian_blocks) {
  EXPECT_TRUE(report.ok()) << report.text();
  int checked_blocks = 0;
  for (const auto& c : report.checks) {
    EXPECT_LE(c.discrepancy, kPassing) << c.callback << "\n" << report.text();
    if (c.checked && c.callback.starts_with("hessian.")) ++checked_blocks;
  }
  EXPECT_EQ(checked_blocks, analytic_hessian_blocks) << report.text();
}

TEST(CheckLagrangian, BuiltInModelsPass) {
  const CheckLagrangianOptions options;
  expect_passes(check_lagrangian<SO3>(mechanics::RigidBody(inertia3()), options), 4);
  expect_passes(check_lagrangian<SO3>(mechanics::SO3Oscillator(inertia3()), options), 4);
  expect_passes(check_lagrangian<groups::Heisenberg>(mechanics::h3_oscillator(), options), 4);
  expect_passes(check_lagrangian<groups::Heisenberg>(mechanics::H3Oscillator(inertia3()), options), 4);
  const Eigen::Vector3d se2_diagonal(3.0, 3.0, 0.7);
  expect_passes(check_lagrangian<groups::SE2>(mechanics::SE2FreeBody(se2_diagonal.asDiagonal().toDenseMatrix()), options), 4);
  Eigen::Matrix<double, 6, 1> se3_diagonal;
  se3_diagonal << 2.0, 2.0, 2.0, 0.5, 0.8, 1.1;
  expect_passes(check_lagrangian<groups::SE3>(mechanics::SE3FreeBody(se3_diagonal.asDiagonal().toDenseMatrix()), options), 4);
  // The spatial rigid body is right-reduced: its group gradient is d/de l(exp(e w) g, v), and it
  // has no analytic hessian.
  CheckLagrangianOptions right = options;
  right.side = groups::Side::Right;
  const mechanics::SpatialRigidBody spatial{mechanics::RigidBody(inertia3())};
  expect_passes(check_lagrangian<SO3>(spatial, right), 0);
  // ... and with the left convention its (nonzero) group gradient is wrong.
  EXPECT_EQ(check_lagrangian<SO3>(spatial, options).failing(), std::vector<std::string>{"group_gradient"});
}

// A wrapper of the SO(3) oscillator with one defect, selected by D; without a hessian unless the
// defect is in the hessian (a user who has none), so that exactly one check can fail.
enum class Defect { GradientSign, MomentumFactor, VelocityNotInverse, HessianBlock, NonFiniteValue, Throws };

template <Defect D>
struct Broken {
  mechanics::SO3Oscillator model{inertia3()};
  double scale = 1;  // the whole Lagrangian multiplied by scale

  double value(double t, const SO3::Element& g, const SO3::Tangent& v) const {
    if constexpr (D == Defect::NonFiniteValue) {
      if (v[0] > 0) return std::numeric_limits<double>::quiet_NaN();
    }
    return scale * model.value(t, g, v);
  }
  SO3::Tangent momentum(double t, const SO3::Element& g, const SO3::Tangent& v) const {
    return (D == Defect::MomentumFactor ? 2 : 1) * scale * model.momentum(t, g, v);
  }
  SO3::Tangent group_gradient(double t, const SO3::Element& g, const SO3::Tangent& v) const {
    if constexpr (D == Defect::Throws) throw std::runtime_error("group_gradient: not implemented");
    return (D == Defect::GradientSign ? -1 : 1) * scale * model.group_gradient(t, g, v);
  }
  SO3::Tangent velocity(double t, const SO3::Element& g, const SO3::Tangent& mu) const {
    const double factor = D == Defect::MomentumFactor ? 2 : 1;  // the inverse of the (wrong) momentum
    const SO3::Tangent v = model.velocity(t, g, mu / (factor * scale));
    return D == Defect::VelocityNotInverse ? SO3::Tangent(v * (1 + 1e-4)) : v;
  }
};

struct BrokenHessian : Broken<Defect::HessianBlock> {
  mechanics::LagrangianHessian<SO3> hessian(double t, const SO3::Element& g, const SO3::Tangent& v) const {
    mechanics::LagrangianHessian<SO3> h = model.hessian(t, g, v);
    h.gradient_g.transposeInPlace();  // a plausible slip: d zeta/d gamma is not symmetric off the identity
    return h;
  }
};

const mechanics::CallbackCheck& entry(const CheckReport& report, const std::string& callback) {
  for (const auto& c : report.checks) {
    if (c.callback == callback) return c;
  }
  throw std::logic_error("no check " + callback);
}

TEST(CheckLagrangian, EachDefectFailsExactlyItsCheck) {
  // A sign error flips zeta: |(-d) - d| / |d| = 2.
  const CheckReport sign = check_lagrangian<SO3>(Broken<Defect::GradientSign>{});
  EXPECT_EQ(sign.failing(), std::vector<std::string>{"group_gradient"}) << sign.text();
  EXPECT_NEAR(entry(sign, "group_gradient").discrepancy, 2.0, 1e-6);
  // A factor 2 in momentum (velocity its inverse): |2 d - d| / |2 d| = 1/2.
  const CheckReport factor = check_lagrangian<SO3>(Broken<Defect::MomentumFactor>{});
  EXPECT_EQ(factor.failing(), std::vector<std::string>{"momentum"}) << factor.text();
  EXPECT_NEAR(entry(factor, "momentum").discrepancy, 0.5, 1e-6);
  // velocity off by a relative 1e-4: discrepancy 1e-4 / (1 + 1e-4).
  const CheckReport inverse = check_lagrangian<SO3>(Broken<Defect::VelocityNotInverse>{});
  EXPECT_EQ(inverse.failing(), std::vector<std::string>{"velocity"}) << inverse.text();
  EXPECT_NEAR(entry(inverse, "velocity").discrepancy, 1e-4 / (1 + 1e-4), 1e-12);
  // A transposed d zeta/d gamma.
  const CheckReport hessian = check_lagrangian<SO3>(BrokenHessian{});
  EXPECT_EQ(hessian.failing(), std::vector<std::string>{"hessian.gradient_g"}) << hessian.text();
  EXPECT_GT(entry(hessian, "hessian.gradient_g").discrepancy, 0.1);
}

TEST(CheckLagrangian, ReportNamesTheFailingCallbackTheSizeAndTheSample) {
  const CheckReport sign = check_lagrangian<SO3>(Broken<Defect::GradientSign>{});
  const std::string text = sign.text();
  EXPECT_NE(text.find("check_lagrangian: FAIL (group_gradient)"), std::string::npos) << text;
  EXPECT_NE(text.find("group_gradient: FAIL, relative discrepancy 2.00e+00"), std::string::npos) << text;
  EXPECT_NE(text.find("momentum: PASS"), std::string::npos) << text;
  const auto& c = entry(sign, "group_gradient");
  ASSERT_GE(c.sample, 0);
  EXPECT_NE(text.find("at sample " + std::to_string(c.sample) + ": t = "), std::string::npos) << text;
}

// The model multiplied by 1e8 or 1e-8 passes with the same discrepancies (relative errors), and
// the sign error still fails at 1e-8, where every absolute difference is below 1e-8.
TEST(CheckLagrangian, ScaleDoesNotFoolIt) {
  for (double scale : {1e-8, 1.0, 1e8}) {
    Broken<Defect::HessianBlock> good;  // no defect outside the hessian, and no hessian
    good.scale = scale;
    const CheckReport report = check_lagrangian<SO3>(good);
    EXPECT_TRUE(report.ok()) << "scale " << scale << "\n" << report.text();
    Broken<Defect::GradientSign> bad;
    bad.scale = scale;
    const CheckReport failing = check_lagrangian<SO3>(bad);
    EXPECT_EQ(failing.failing(), std::vector<std::string>{"group_gradient"}) << "scale " << scale;
    EXPECT_NEAR(entry(failing, "group_gradient").discrepancy, 2.0, 1e-6) << "scale " << scale;
  }
}

TEST(CheckLagrangian, NonFiniteValuesAndExceptionsAreReported) {
  const CheckReport nan = check_lagrangian<SO3>(Broken<Defect::NonFiniteValue>{});
  EXPECT_FALSE(nan.ok());
  const auto& m = entry(nan, "momentum");
  EXPECT_FALSE(m.ok);
  EXPECT_TRUE(std::isinf(m.discrepancy));
  EXPECT_EQ(m.note, "value returned a non-finite value near the sample");
  EXPECT_TRUE(entry(nan, "velocity").ok);  // value is not used there
  EXPECT_NE(nan.text().find("value returned a non-finite value"), std::string::npos);

  const CheckReport thrown = check_lagrangian<SO3>(Broken<Defect::Throws>{});
  EXPECT_EQ(thrown.failing(), std::vector<std::string>{"group_gradient"});
  EXPECT_EQ(entry(thrown, "group_gradient").note, "threw: group_gradient: not implemented");
}

TEST(CheckLagrangian, SamplesGivenOrSeeded) {
  CheckLagrangianOptions options;
  options.samples = 3;
  options.scale = 0.5;
  const auto samples = mechanics::lagrangian_samples<SO3>(options);
  ASSERT_EQ(samples.size(), 3u);
  for (const auto& s : samples) {
    EXPECT_GE(s.t, 0);
    EXPECT_LE(s.t, 0.5);
    EXPECT_LE(s.v.cwiseAbs().maxCoeff(), 0.5);
    EXPECT_LE(SO3::log(s.g).cwiseAbs().maxCoeff(), 0.5 + 1e-12);
  }
  // Deterministic: the same seed gives the same points, another seed others.
  EXPECT_EQ(mechanics::lagrangian_samples<SO3>(options)[2].v, samples[2].v);
  options.seed += 1;
  EXPECT_NE(mechanics::lagrangian_samples<SO3>(options)[2].v, samples[2].v);
  // Given samples, the identity with v = 0 among them (zero derivatives compare as equal).
  std::vector<mechanics::LagrangianSample<SO3>> given{{0.0, SO3::identity(), SO3::Tangent::Zero()}, samples[0]};
  const CheckReport report = check_lagrangian<SO3>(mechanics::SO3Oscillator(inertia3()), given);
  EXPECT_TRUE(report.ok()) << report.text();
  EXPECT_EQ(report.samples, 2);
}

TEST(CheckLagrangian, InvalidArgumentsNameTheValue) {
  const mechanics::RigidBody body(inertia3());
  CheckLagrangianOptions options;
  options.samples = 0;
  expect_invalid([&] { check_lagrangian<SO3>(body, options); }, {"check_lagrangian", "samples = 0"});
  options.samples = 2;
  options.scale = std::numeric_limits<double>::quiet_NaN();
  expect_invalid([&] { check_lagrangian<SO3>(body, options); }, {"scale = nan", "finite and positive"});
  expect_invalid([&] { check_lagrangian<SO3>(body, std::vector<mechanics::LagrangianSample<SO3>>{}); }, "samples");
  std::vector<mechanics::LagrangianSample<SO3>> bad{{std::numeric_limits<double>::infinity(), SO3::identity(), SO3::Tangent::Zero()}};
  expect_invalid([&] { check_lagrangian<SO3>(body, bad); }, {"sample 0", "is not finite"});
}

}  // namespace
}  // namespace cartan::testing
