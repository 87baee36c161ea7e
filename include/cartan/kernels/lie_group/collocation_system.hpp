#pragma once
// The transported-velocity BVP (eq:reduced-system) on any Lie group, for the collocation solver,
// with the group element g and the transport element h (P = Ad(h), as in kernels/lie_group/scheme.hpp)
// as states in the ambient coordinates of G::Element (a 3x3 matrix for SO(3), (a, b, c) for H3):
//   u = Ad(h) v,   g' = d(L_g)_e u,   h' = d(R_h)_e (-lambda u)      (P' = -lambda ad_u P, disc-exp)
//   mu' = P^T zeta - (2 lambda - 1) ad*_v mu - lambda (1 - lambda) ad*_v xi,   mu = I v
//   xi' = -ad*_v mu
// for natural Lagrangians (mu = I v with constant I, so v' = I^{-1} mu'). Boundary conditions:
// all ambient entries of g(0) = g0 and h(0) = e, then log(gT^{-1} g(T)) = 0 and xi(T) = 0: as
// many as states. The exact flow keeps g and h on the group (e.g. orthogonal for SO(3)); the
// collocation solution leaves it only by the discretisation error, which the caller can measure.
// For H3 the transport has a closed form and kernels/lie_group/heisenberg_collocation.hpp is the paper's
// printed system; this generic form agrees with it (tests/kernels/lie_group/test_collocation_system.cpp).

#include <algorithm>
#include <concepts>

#include "cartan/errors.hpp"
#include "cartan/groups/so3.hpp"
#include "cartan/kernels/lie_group/scheme.hpp"
#include "cartan/mechanics/natural_system.hpp"
#include "cartan/numerics/collocation.hpp"
#include "cartan/principle/group_problem.hpp"
#include "cartan/transport/disc_exp.hpp"

namespace cartan::transported {

template <groups::LieGroup G, mechanics::Potential<G> V>
class TransportedCollocation {
 public:
  using Problem = TransportedProblem<G, mechanics::NaturalLagrangian<G, V>>;
  static constexpr int kElement = static_cast<int>(groups::ElementOf<G>::SizeAtCompileTime);
  static constexpr int kDim = G::kDim;
  static constexpr int kStates = 2 * kElement + 2 * kDim;
  // Offsets of g, h, v, xi in the state.
  static constexpr int kG = 0, kH = kElement, kV = 2 * kElement, kXi = 2 * kElement + kDim;

  static groups::ElementOf<G> element(numerics::ConstVectorRef y, int offset) {
    return Eigen::Map<const groups::ElementOf<G>>(y.data() + offset);
  }

  static numerics::BvpSystem system(const Problem& problem) {
    numerics::BvpSystem s;
    s.n = kStates;
    s.rhs = [problem](double t, numerics::ConstVectorRef y, numerics::ConstVectorRef, numerics::VectorRef dy) {
      const groups::ElementOf<G> g = element(y, kG), h = element(y, kH);
      const groups::TangentOf<G> v = y.template segment<kDim>(kV);
      const groups::CovectorOf<G> xi = y.template segment<kDim>(kXi);
      const auto& l = problem.lagrangian;
      const double lambda = problem.lambda;
      const groups::AlgebraMatrixOf<G> transport = G::Ad(h);
      const groups::TangentOf<G> u = transport * v;
      const groups::CovectorOf<G> mu = l.momentum(t, g, v);
      const groups::CovectorOf<G> coad_v_mu = groups::coad<G>(v, mu);
      const groups::CovectorOf<G> dmu = transport.transpose() * l.group_gradient(t, g, v) - (2 * lambda - 1) * coad_v_mu -
                                lambda * (1 - lambda) * groups::coad<G>(v, xi);
      Eigen::Map<groups::ElementOf<G>>(dy.data() + kG) = G::left_translate(g, u);
      Eigen::Map<groups::ElementOf<G>>(dy.data() + kH) = G::right_translate(h, groups::TangentOf<G>(-lambda * u));
      dy.template segment<kDim>(kV) = l.velocity(t, g, dmu);
      dy.template segment<kDim>(kXi) = -coad_v_mu;
    };
    s.bc = [g0 = problem.g0, gT_inverse = G::inverse(problem.gT)](numerics::ConstVectorRef ya, numerics::ConstVectorRef yb,
                                                                   numerics::ConstVectorRef, numerics::VectorRef r) {
      r.template segment<kElement>(kG) = (element(ya, kG) - g0).reshaped();
      r.template segment<kElement>(kH) = (element(ya, kH) - G::identity()).reshaped();
      r.template segment<kDim>(kV) = G::log(G::compose(gT_inverse, element(yb, kG)));
      r.template segment<kDim>(kXi) = yb.template segment<kDim>(kXi);
    };
    return s;
  }

  /// The geodesic guess on a uniform mesh of problem.N intervals: u = w / T constant with
  /// w = log(g0^{-1} gT), so g = g0 exp(t u), h = exp(-lambda t u), v = Ad(h)^{-1} u = u, xi = 0.
  static void geodesic_guess(const Problem& problem, Eigen::VectorXd& t, Eigen::MatrixXd& y) {
    const groups::TangentOf<G> u = groups::log_between<G>(problem.g0, problem.gT) / problem.T;
    t = Eigen::VectorXd::LinSpaced(problem.N + 1, 0, problem.T);
    y.setZero(kStates, t.size());
    for (Eigen::Index i = 0; i < t.size(); ++i) {
      const groups::ElementOf<G> g = G::compose(problem.g0, G::exp(groups::TangentOf<G>(t[i] * u)));
      const groups::ElementOf<G> h = G::exp(groups::TangentOf<G>(-problem.lambda * t[i] * u));
      y.col(i).template segment<kElement>(kG) = g.reshaped();
      y.col(i).template segment<kElement>(kH) = h.reshaped();
      y.col(i).template segment<kDim>(kV) = u;
    }
  }

  /// An initial guess from a discrete solution (e.g. a shooting solver's, whose solution branch
  /// the collocation then refines): its nodes as the mesh, g, v, xi as given, and the transport
  /// element rebuilt along the piecewise-geodesic path, h_{k+1} = exp(-lambda dt u_k) h_k with
  /// u_k = log(g_k^{-1} g_{k+1}) / dt (disc-exp, exact on each geodesic step).
  static void guess_from(const Problem& problem, const TransportedTrajectory<G>& trajectory, Eigen::VectorXd& t,
                         Eigen::MatrixXd& y) {
    const auto m = static_cast<Eigen::Index>(trajectory.t.size());
    if (m < 2) throw_invalid("TransportedCollocation::guess_from", "trajectory.t.size()", std::to_string(m), "must be at least 2");
    t = Eigen::Map<const Eigen::VectorXd>(trajectory.t.data(), m);
    y.setZero(kStates, m);
    groups::ElementOf<G> h = G::identity();
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto k = static_cast<std::size_t>(i);
      y.col(i).template segment<kElement>(kG) = trajectory.g[k].reshaped();
      y.col(i).template segment<kElement>(kH) = h.reshaped();
      y.col(i).template segment<kDim>(kV) = trajectory.v[k];
      y.col(i).template segment<kDim>(kXi) = trajectory.xi[k];
      if (i + 1 < m) {
        const double dt = t[i + 1] - t[i];
        const groups::TangentOf<G> u = groups::log_between<G>(trajectory.g[k], trajectory.g[k + 1]) / dt;
        h = transport::disc_exp_update<G>(problem.lambda, dt, u, h);
      }
    }
  }

  /// For SO(3): the largest departure of g and the transport element h from orthogonality over
  /// the mesh nodes, max |M^T M - I|. The exact flow keeps it 0; the collocation solution leaves
  /// the group only by its discretisation error.
  static double orthogonality_defect(const numerics::BvpResult& solution)
    requires std::same_as<G, groups::SO3>
  {
    double worst = 0;
    for (Eigen::Index i = 0; i < solution.t.size(); ++i) {
      for (int offset : {kG, kH}) {
        const groups::SO3::Element m = element(solution.y.col(i), offset);
        worst = std::max(worst, (m.transpose() * m - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
      }
    }
    return worst;
  }

  static numerics::BvpResult solve(const Problem& problem, const numerics::CollocationOptions& options) {
    problem.validate();
    Eigen::VectorXd t;
    Eigen::MatrixXd y;
    geodesic_guess(problem, t, y);
    return numerics::solve_collocation(system(problem), t, y, Eigen::VectorXd(0), options);
  }
};

}  // namespace cartan::transported
