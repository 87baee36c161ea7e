#pragma once
// The words of the transported-velocity problem (DESIGN.md, layer "principle"): the methods and
// continuation paths of every solve, its defaults, and the orders results report, one spelling
// for C++, the CLI (--method, --continuation, JSON `method`) and Python (method=, continuation=),
// whichever kernel runs (the Lie group's, kernels/lie_group/; the general manifold's, kernels/manifold/).

#include <array>
#include <string_view>
#include <utility>

#include "cartan/enum_names.hpp"
#include "cartan/scheme_order.hpp"

namespace cartan {

enum class Method {
  Auto,              ///< the default strategy: tries the others in turn
  Shooting,          ///< augmented shooting on (v0, and xi0 or Xi0) with an analytic Jacobian
  MultipleShooting,  ///< lifted Levenberg–Marquardt over segments of the same scheme (Lie-group kernel)
  TwoLevel,          ///< the paper's scheme: inner shooting on v0, outer fixed point on xi (Lie-group kernel)
  Collocation,       ///< fourth-order adaptive collocation of the continuous problem
  Variational,       ///< Newton on the discrete Euler–Lagrange equations of S_h (Lie-group kernel)
};

/// How shooting (and collocation, for its start) reaches a problem that fails from the guess:
/// not at all, by continuation in the horizon T, or in lambda (from lambda_start).
enum class Continuation { None, T, Lambda };

/// The default tolerance and iteration limit of every solve: SolveOptions, the CLI's --tol and
/// --max-iterations, Python's tol= and max_iterations= (cartan._cartan.DEFAULTS) take them from here.
inline constexpr double kDefaultTol = 1e-10;
inline constexpr int kDefaultMaxIterations = 200;

/// Collocation's mesh limit when none is given (the CLI, Python, both kernels): ample for
/// tol >= 1e-12 on the paper's problems (~1000 nodes at 1e-10 on H3; the SO(3) paper cases need
/// fewer than 5000 at 1e-10).
inline constexpr int kDefaultMaxNodes = 20000;

/// The variational integrator's order (methods/lie_group/variational.hpp; measured in
/// tests/kernels/lie_group/test_variational.cpp). Collocation's is kCollocationOrder (scheme_order.hpp).
inline constexpr int kVariationalOrder = 2;

template <>
struct EnumNames<Method> {
  static constexpr std::string_view what = "method";
  static constexpr std::array<std::pair<Method, std::string_view>, 6> names{{
      {Method::Auto, "auto"},
      {Method::Shooting, "shooting"},
      {Method::MultipleShooting, "multiple-shooting"},
      {Method::TwoLevel, "two-level"},
      {Method::Collocation, "collocation"},
      {Method::Variational, "variational"},
  }};
};

template <>
struct EnumNames<Continuation> {
  static constexpr std::string_view what = "continuation";
  static constexpr std::array<std::pair<Continuation, std::string_view>, 3> names{{
      {Continuation::None, "none"},
      {Continuation::T, "T"},
      {Continuation::Lambda, "lambda"},
  }};
};

}  // namespace cartan
