#pragma once
// Validation helpers used at every public entry point.
//
// cartan has three kinds of error handling (STYLE.md, practice 7):
//   * static_assert / concepts for misuse of types;
//   * std::invalid_argument (bad values) and std::domain_error (values outside a map's domain)
//     thrown at API boundaries, with the offending value printed in the message;
//   * result objects with a status for numerical outcomes (non-convergence), never exceptions;
//     a defective model callback is not such an outcome: ModelError (an invalid_argument).

#include <Eigen/Core>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cartan {

/// A model callback (a Lagrangian's momentum, say) returned an unusable value from valid
/// arguments: a defect of the model, not a numerical outcome. The solvers, which turn other
/// exceptions inside a sweep into a failed iterate, let it through, so the caller sees it at once.
class ModelError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Prints a number with the fewest digits that read back as the same double (0.4, 1e-18), or a
/// vector or matrix on one line, rows separated by ';', its entries so.
std::string format_value(const Eigen::Ref<const Eigen::MatrixXd>& x);
std::string format_value(double x);

/// User-supplied text for a message: in double quotes, control and non-ASCII bytes escaped as
/// `\xNN`, cut to 60 characters (then "..." follows), so that hostile input cannot flood or
/// corrupt a terminal.
std::string quote_input(std::string_view text);

/// Numbers separated by commas (the fewest digits that read back exactly), cut after about 60 characters ("...").
std::string excerpt(const std::vector<double>& values);

/// Throws std::invalid_argument("<where>: <name> = <value> <problem>").
[[noreturn]] void throw_invalid(std::string_view where, std::string_view name,
                                const std::string& value, std::string_view problem);

/// Throws std::invalid_argument unless every entry of x is finite.
void require_finite(const Eigen::Ref<const Eigen::MatrixXd>& x, std::string_view where,
                    std::string_view name);
void require_finite(double x, std::string_view where, std::string_view name);

/// Throws std::invalid_argument unless tol (finite, the caller checks) is positive and at least 100
/// machine epsilons: every method's residual carries the rounding of many operations, so below
/// that no method can meet tol (SolveOptions, CollocationOptions).
void require_reachable_tolerance(double tol, std::string_view where, std::string_view name = "tol");

/// Throws std::invalid_argument unless x has the given shape.
void require_shape(const Eigen::Ref<const Eigen::MatrixXd>& x, Eigen::Index rows, Eigen::Index cols,
                   std::string_view where, std::string_view name);

}  // namespace cartan
