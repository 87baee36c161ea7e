#pragma once
// The outcome of every numerical solver in cartan (STYLE.md practice 7, like Eigen's
// ComputationInfo): the nonlinear solver, the collocation BVP solver, and every solver of the
// transported-velocity problem. Details go into the result's `message`; code compares the enum,
// and the CLI's JSON, Python results and sweep tables print the same words (to_string).

#include <array>
#include <string_view>
#include <utility>

#include "cartan/enum_names.hpp"

namespace cartan {

enum class Status {
  Converged,           ///< every convergence test met
  MaxIterations,       ///< the iteration budget ran out
  Stalled,             ///< steps became negligible while the residual stayed above tolerance
  NonFinite,           ///< a residual, Jacobian or state became NaN or infinite
  SingularJacobian,    ///< a linear system could not be solved
  NoProgress,          ///< abandoned early: the residual stopped decreasing (a hopeless start)
  MaxNodesExceeded,    ///< collocation: refinement would need more than max_nodes nodes
  NotConverged,        ///< collocation: Newton or mesh refinement failed
  InnerNotConverged,   ///< two-level: the inner shooting loop failed
  OuterNotConverged,   ///< two-level: the outer fixed point did not settle
  Inconsistent,        ///< multiple shooting: the lifted system converged, one plain sweep does not
  ContinuationFailed,  ///< continuation could not reach the requested parameter
  StrategyFailed,      ///< every method of the default strategy failed
  Interrupted,         ///< stopped on request (Ctrl-C, a callback error, a cancelled solve)
  TimeLimit,           ///< stopped when the time limit (SolveOptions::time_limit) ran out
};

/// Stopped on request (a cancellation or the time limit), not ended by the method: such a result
/// carries its best iterate's samples and nothing computed from them afterwards (no action).
constexpr bool stopped_on_request(Status status) { return status == Status::Interrupted || status == Status::TimeLimit; }

template <>
struct EnumNames<Status> {
  static constexpr std::string_view what = "status";
  static constexpr std::array<std::pair<Status, std::string_view>, 15> names{{
      {Status::Converged, "converged"},
      {Status::MaxIterations, "max-iterations"},
      {Status::Stalled, "stalled"},
      {Status::NonFinite, "non-finite"},
      {Status::SingularJacobian, "singular-jacobian"},
      {Status::NoProgress, "no-progress"},
      {Status::MaxNodesExceeded, "max-nodes-exceeded"},
      {Status::NotConverged, "not-converged"},
      {Status::InnerNotConverged, "inner-not-converged"},
      {Status::OuterNotConverged, "outer-not-converged"},
      {Status::Inconsistent, "inconsistent"},
      {Status::ContinuationFailed, "continuation-failed"},
      {Status::StrategyFailed, "strategy-failed"},
      {Status::Interrupted, "interrupted"},
      {Status::TimeLimit, "time-limit"},
  }};
};

}  // namespace cartan
