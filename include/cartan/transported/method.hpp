#pragma once
// The names of the transported-velocity solvers and of their continuation paths, one spelling
// for C++, the CLI (--method, --continuation, JSON `method`) and Python (method=, continuation=).

#include <array>
#include <string_view>
#include <utility>

#include "cartan/enum_names.hpp"
#include "cartan/scheme_order.hpp"

namespace cartan::transported {

enum class Method {
  Auto,              ///< the default strategy (transported/solve.hpp): tries the others in turn
  Shooting,          ///< augmented shooting on (v0, xi0) with an analytic Jacobian
  MultipleShooting,  ///< lifted Levenberg–Marquardt over segments of the same scheme
  TwoLevel,          ///< the paper's scheme: inner shooting on v0, outer fixed point on xi
  Collocation,       ///< fourth-order adaptive collocation of the continuous problem
  Variational,       ///< Newton on the discrete Euler–Lagrange equations of S_h (variational.hpp)
};

/// How shooting (and collocation, for its start) reaches a problem that fails from the guess:
/// not at all, by continuation in the horizon T, or in lambda (from lambda_start).
enum class Continuation { None, T, Lambda };

/// The default tolerance and iteration limit of every solve: SolveOptions, the CLI's --tol and
/// --max-iterations, Python's tol= and max_iterations= (cartan._cartan.DEFAULTS) take them from here.
inline constexpr double kDefaultTol = 1e-10;
inline constexpr int kDefaultMaxIterations = 200;

/// The collocation scheme's order (scheme_order.hpp), reported as `order`.
using ::cartan::kCollocationOrder;
/// The variational integrator's order (variational.hpp; measured in tests/transported/test_variational.cpp).
inline constexpr int kVariationalOrder = 2;

}  // namespace cartan::transported

// The words of each enum (enum_names.hpp); specialisations live in the template's namespace.
namespace cartan {

template <>
struct EnumNames<transported::Method> {
  static constexpr std::string_view what = "method";
  static constexpr std::array<std::pair<transported::Method, std::string_view>, 6> names{{
      {transported::Method::Auto, "auto"},
      {transported::Method::Shooting, "shooting"},
      {transported::Method::MultipleShooting, "multiple-shooting"},
      {transported::Method::TwoLevel, "two-level"},
      {transported::Method::Collocation, "collocation"},
      {transported::Method::Variational, "variational"},
  }};
};

template <>
struct EnumNames<transported::Continuation> {
  static constexpr std::string_view what = "continuation";
  static constexpr std::array<std::pair<transported::Continuation, std::string_view>, 3> names{{
      {transported::Continuation::None, "none"},
      {transported::Continuation::T, "T"},
      {transported::Continuation::Lambda, "lambda"},
  }};
};

}  // namespace cartan
