// api::verify: the checks of verify/ on samples in numbers, for the problem's kernel (solve.hpp).
#include "problems.hpp"

#include "cartan/errors.hpp"

namespace cartan::api {

namespace {

using detail::value_of_row;

/// Throws "<where>: samples.<name> = (r x c numbers) must have <rows> rows of <width>" unless it has.
void require_table(const Eigen::MatrixXd& x, const char* name, Eigen::Index rows, Eigen::Index width, std::string_view where) {
  if (x.rows() == rows && x.cols() == width) return;
  throw_invalid(where, std::string("samples.") + name, "(" + std::to_string(x.rows()) + " x " + std::to_string(x.cols()) + " numbers)",
                "must have " + std::to_string(rows) + " rows (one per time) of " + std::to_string(width) + " numbers");
}

/// Checks the shapes of `x` against an element of `element_size` numbers and an auxiliary of
/// `aux_width` numbers, for an algebra of dimension n.
void check_samples(const Samples& x, Eigen::Index element_size, Eigen::Index n, Eigen::Index aux_width, std::string_view where) {
  const Eigen::Index m = x.t.size();
  require_table(x.points, "points", m, element_size, where);
  require_table(x.v, "v", m, n, where);
  require_table(x.mu, "mu", m, n, where);
  require_table(x.aux, "aux", m, aux_width, where);
}

std::vector<double> times(const Samples& x) { return {x.t.data(), x.t.data() + x.t.size()}; }

template <groups::LieGroup G>
transported::TransportedTrajectory<G> lie_trajectory(const Samples& x) {
  transported::TransportedTrajectory<G> out;
  out.t = times(x);
  for (Eigen::Index k = 0; k < x.t.size(); ++k) {
    out.g.push_back(value_of_row<groups::ElementOf<G>>(x.points, k));
    out.v.push_back(value_of_row<groups::TangentOf<G>>(x.v, k));
    out.mu.push_back(value_of_row<groups::CovectorOf<G>>(x.mu, k));
    out.xi.push_back(value_of_row<groups::CovectorOf<G>>(x.aux, k));
  }
  return out;
}

template <manifolds::ManifoldWithConnection M>
general::GeneralTrajectory<M> general_trajectory(const Samples& x) {
  general::GeneralTrajectory<M> out;
  out.t = times(x);
  for (Eigen::Index k = 0; k < x.t.size(); ++k) {
    out.q.push_back(value_of_row<manifolds::PointOf<M>>(x.points, k));
    out.v.push_back(value_of_row<manifolds::ComponentsOf<M>>(x.v, k));
    out.mu.push_back(value_of_row<manifolds::ComponentsOf<M>>(x.mu, k));
    out.Xi.push_back(value_of_row<manifolds::ComponentMatrixOf<M>>(x.aux, k));
  }
  return out;
}

/// The numbers as the element they write, not projected (the checks see the data).
template <groups::LieGroup G>
groups::ElementOf<G> element(const std::vector<double>& numbers) {
  const Eigen::Map<const Eigen::RowVectorXd> row(numbers.data(), static_cast<Eigen::Index>(numbers.size()));
  return value_of_row<groups::ElementOf<G>>(Eigen::MatrixXd(row), 0);
}

}  // namespace

verify::Report verify(const GroupProblem& problem, const Samples& samples, int order, double tol, Status status,
                      std::string_view where) {
  const detail::CheckedGroupProblem checked = detail::checked(problem, {}, true, where);
  const Eigen::Index n = checked.model->dim;
  check_samples(samples, static_cast<Eigen::Index>(checked.model->element_size), n, lie_kernel(problem) ? n : n * n, where);
  return models::visit_model(problem.group, problem.model, where, [&]<class Entry>(const Entry&) {
    using G = typename Entry::Table::Group;
    const groups::ElementOf<G> g0 = element<G>(checked.g0), gT = element<G>(problem.gT);
    if (lie_kernel(problem)) {
      // Behind the erased Lagrangian, whose verify the library compiles: the model's own members
      // evaluated, so the figures of the typed verify (tests/kernels/lie_group/test_erased.cpp).
      const transported::ErasedProblem<G> erased{mechanics::ErasedLagrangian<G>(models::make_lagrangian<Entry>(checked.inertia, where)),
                                                 problem.lambda, problem.T, problem.N, g0, gT};
      return verify::verify_trajectory(erased, lie_trajectory<G>(samples), order, tol, status);
    }
    return general::verify_general(detail::connection_problem<Entry>(problem, checked, g0, gT, where),
                                   general_trajectory<manifolds::GroupManifold<G>>(samples), order, tol, status);
  });
}

verify::Report verify(const ManifoldProblem& problem, const Samples& samples, int order, double tol, Status status,
                      std::string_view where) {
  return detail::visit_manifold(problem, {}, where, [&]<class M>(const general::ErasedProblem<M>& posed) {
    check_samples(samples, manifolds::PointOf<M>::SizeAtCompileTime, M::kDim, M::kDim * M::kDim, where);
    return general::verify_general(posed, general_trajectory<M>(samples), order, tol, status);
  });
}

}  // namespace cartan::api
