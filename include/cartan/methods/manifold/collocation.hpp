#pragma once
// The general transported-velocity problem (principle/manifold_problem.hpp) as a continuous two-point BVP for the
// library's collocation solver (numerics/collocation.hpp), in the ambient storage of the instance:
//   state y = (q, E, mu, Xi): the point's storage (a unit vector of R^3, a group element, ...),
//   the frame E (d x m), mu (m), Xi (m x m); v = velocity(t, q, mu) (the inverse Legendre map);
//   q' = point_velocity(q, E v),   E' = -Gamma_q(E v, E),   mu' = the local form (scheme.hpp's rates),
//   Xi' = -v mu^T,
// with the boundary conditions y(0) = (q0, frame0) in every stored entry, then
// difference(qT, q(T)) = 0 in the components of tangent_basis(qT) and Xi(T) = 0: as many as states
// (as the Lie-group form, kernels/lie_group/collocation_system.hpp). The exact flow keeps q on Q and E
// tangent; the collocation solution leaves them only by its discretisation error.
// Where nabla T = nabla R = 0 the frame components of T and R are constant along the exact solution
// and are computed once (the scheme's fast path), otherwise from Gamma at every evaluation.

#include <chrono>
#include <memory>
#include <string>

#include "cartan/kernels/manifold/scheme.hpp"
#include "cartan/methods/manifold/shooting.hpp"
#include "cartan/numerics/collocation.hpp"
#include "cartan/principle/options.hpp"
#include "cartan/principle/result.hpp"
#include "cartan/principle/vocabulary.hpp"
#include "cartan/solvers/collocation.hpp"

namespace cartan::general {

template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
class GeneralCollocation {
 public:
  static constexpr int m = M::kDim, d = M::kAmbientDim;
  static constexpr int kPoint = static_cast<int>(manifolds::PointOf<M>::SizeAtCompileTime);
  static_assert(kPoint > 0, "collocation stores the point in its fixed-size storage");
  /// Offsets of q, E, mu, Xi in the state.
  static constexpr int kQ = 0, kE = kPoint, kMu = kPoint + d * m, kXi = kMu + m, kStates = kXi + m * m;
  using Node = GeneralNode<M>;

  explicit GeneralCollocation(const GeneralProblem<M, L>& problem)
      : scheme_(std::make_shared<const GeneralScheme<M, L>>(problem, SchemeOrder::First)) {}

  const GeneralProblem<M, L>& problem() const { return scheme_->problem(); }
  /// difference(qT, q) in the components of tangent_basis(qT) (the scheme's terminal residual).
  manifolds::ComponentsOf<M> terminal_residual(const manifolds::PointOf<M>& q) const { return scheme_->terminal_residual(q); }
  bool terminal_residual_defined(const manifolds::PointOf<M>& q) const { return scheme_->terminal_residual_defined(q); }
  double terminal_error(const manifolds::PointOf<M>& q) const { return scheme_->terminal_error(q); }

  /// The node (v from the inverse Legendre map) stored in y at time t.
  Node node(double t, numerics::ConstVectorRef y) const {
    Node n;
    n.t = t;
    n.q = Eigen::Map<const manifolds::PointOf<M>>(y.data() + kQ);
    n.frame = Eigen::Map<const manifolds::FrameOf<M>>(y.data() + kE);
    n.mu = y.template segment<m>(kMu);
    n.Xi = Eigen::Map<const manifolds::ComponentMatrixOf<M>>(y.data() + kXi);
    n.v = scheme_->velocity(t, n.q, n.mu);
    return n;
  }

  static void store(const Node& n, numerics::VectorRef y) {
    Eigen::Map<manifolds::PointOf<M>>(y.data() + kQ) = n.q;
    Eigen::Map<manifolds::FrameOf<M>>(y.data() + kE) = n.frame;
    y.template segment<m>(kMu) = n.mu;
    Eigen::Map<manifolds::ComponentMatrixOf<M>>(y.data() + kXi) = n.Xi;
  }

  numerics::BvpSystem system() const {
    numerics::BvpSystem s;
    s.n = kStates;
    s.rhs = [self = *this](double t, numerics::ConstVectorRef y, numerics::ConstVectorRef, numerics::VectorRef dy) {
      const Node n = self.node(t, y);
      const M& manifold = self.problem().manifold;
      const manifolds::VectorOf<M> u = n.frame * n.v;
      Eigen::Map<manifolds::PointOf<M>>(dy.data() + kQ) = manifolds::point_velocity(manifold, n.q, u);
      Eigen::Map<manifolds::FrameOf<M>> dE(dy.data() + kE);
      for (int i = 0; i < m; ++i) dE.col(i) = -manifold.christoffel(n.q, u, n.frame.col(i));
      dy.template segment<m>(kMu) = self.scheme_->momentum_rate(n);
      Eigen::Map<manifolds::ComponentMatrixOf<M>>(dy.data() + kXi) = -n.v * n.mu.transpose();
    };
    s.bc = [self = *this](numerics::ConstVectorRef ya, numerics::ConstVectorRef yb, numerics::ConstVectorRef,
                          numerics::VectorRef r) {
      const GeneralProblem<M, L>& p = self.problem();
      r.template segment<kPoint>(kQ) = (Eigen::Map<const manifolds::PointOf<M>>(ya.data() + kQ) - p.q0).reshaped();
      r.template segment<d * m>(kE) =
          (Eigen::Map<const manifolds::FrameOf<M>>(ya.data() + kE) - p.initial_frame()).reshaped();
      r.template segment<m>(kMu) = self.terminal_residual(Eigen::Map<const manifolds::PointOf<M>>(yb.data() + kQ));
      r.template segment<m * m>(kXi) = yb.template segment<m * m>(kXi);
    };
    return s;
  }

  /// The states at the nodes of a trajectory (e.g. a shooting solution) as a collocation guess.
  static void guess_from(const GeneralTrajectory<M>& x, Eigen::VectorXd& t, Eigen::MatrixXd& y) {
    const auto count = static_cast<Eigen::Index>(x.t.size());
    t = Eigen::Map<const Eigen::VectorXd>(x.t.data(), count);
    y.resize(kStates, count);
    for (Eigen::Index k = 0; k < count; ++k) {
      const auto j = static_cast<std::size_t>(k);
      store(Node{x.t[j], x.q[j], x.frame[j], x.mu[j], x.Xi[j], x.v[j]}, y.col(k));
    }
  }

  /// The geodesic guess on a uniform mesh of N intervals: the instance's piece from q0 towards qT,
  /// q(t) = step(q0, (t/T) w) with w = difference(q0, qT), the frame transported along it,
  /// v = E0^+ w / T constant, mu = momentum, Xi = (T - t) v mu^T (exact for constant v and mu).
  /// With a `monitor`, polled at a PollPacer's nodes (a chart's steps and transports may call
  /// Python): a stop leaves the remaining nodes at the last one computed, and the solve then stops
  /// at its first poll.
  void geodesic_guess(Eigen::VectorXd& t, Eigen::MatrixXd& y, const SolveMonitor* monitor = nullptr) const {
    const GeneralProblem<M, L>& p = problem();
    const manifolds::VectorOf<M> w = p.manifold.difference(p.q0, p.qT);
    const manifolds::FrameOf<M> frame0 = p.initial_frame();
    const manifolds::ComponentsOf<M> v = manifolds::dual_frame<M>(frame0) * w / p.T;
    t = Eigen::VectorXd::LinSpaced(p.N + 1, 0, p.T);
    y.resize(kStates, t.size());
    PollPacer pacer(SolveMonitor::kStepsBetweenPolls);
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      if (monitor != nullptr && k > 0 && pacer.due(k)) {
        pacer.polled();
        if (SolveMonitor::poll(monitor)) {
          y.rightCols(t.size() - k) = y.col(k - 1).replicate(1, t.size() - k);
          return;
        }
      }
      const manifolds::VectorOf<M> part = (t[k] / p.T) * w;
      Node n;
      n.t = t[k];
      n.q = p.manifold.step(p.q0, part);
      n.frame = p.manifold.transport_along_step(p.q0, part) * frame0;
      n.v = v;
      n.mu = p.lagrangian.momentum(t[k], n.q, v);
      n.Xi = (p.T - t[k]) * v * n.mu.transpose();
      store(n, y.col(k));
    }
  }

 private:
  std::shared_ptr<const GeneralScheme<M, L>> scheme_;
};

/// The collocation result at `times` (ending at T) as a GeneralSolution: the nodes read from the
/// cubic interpolant, the terminal errors, the counters (iterations = Newton iterations, sweeps =
/// Jacobian evaluations) and the mesh report.
template <manifolds::ManifoldWithConnection M, ManifoldLagrangian<M> L>
GeneralSolution<M> general_collocation_solution(const GeneralCollocation<M, L>& collocation,
                                                const numerics::BvpResult& result, const Eigen::VectorXd& times) {
  GeneralSolution<M> s;
  s.status = result.status;
  s.message = "collocation of the continuous general system: " + result.message;
  s.method = Method::Collocation;
  s.order = kCollocationOrder;
  const numerics::CubicHermite interpolant = result.interpolant();
  std::string failure;
  try {
    for (Eigen::Index j = 0; j < times.size(); ++j) s.trajectory.push(collocation.node(times[j], interpolant.value(times[j])));
  } catch (const ModelError&) {
    throw;
  } catch (const std::exception& e) {  // the inverse Legendre map failed on a diverged iterate
    s.trajectory = {};
    if (s.status == Status::Converged) s.status = Status::NonFinite;
    s.message += std::string("; no output: ") + e.what();
  }
  const auto& x = s.trajectory;
  if (!x.t.empty()) {
    s.v0 = x.v.front();
    s.Xi0 = x.Xi.front();
    s.terminal_error = collocation.terminal_error(x.q.back());
    s.xi_terminal = x.Xi.back().norm();
    if (s.converged() && !collocation.terminal_residual_defined(x.q.back())) {  // never a wrong "converged"
      s.status = Status::NotConverged;
      s.message += "; q(T) is where difference(qT, .) is not defined (the cut locus of qT), " +
                   format_value(s.terminal_error) + " from qT";
    }
  }
  s.collocation = CollocationReport{static_cast<int>(result.t.size()), result.max_rms_residual};
  s.inner_iterations = result.newton_iterations;
  s.sweeps = result.jacobian_evaluations;
  return s;
}

}  // namespace cartan::general
