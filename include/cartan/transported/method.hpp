#pragma once
// The names of the transported-velocity solvers and of their continuation paths, one spelling
// for C++, the CLI (--method, --continuation, JSON `method`) and Python (method=, continuation=).

#include <array>
#include <string_view>
#include <utility>

#include "cartan/enum_names.hpp"

namespace cartan {

enum class Method {
  Auto,              ///< the default strategy (transported/solve.hpp): tries the others in turn
  Shooting,          ///< augmented shooting on (v0, xi0) with an analytic Jacobian
  MultipleShooting,  ///< lifted Levenberg–Marquardt over segments of the same scheme
  TwoLevel,          ///< the paper's scheme: inner shooting on v0, outer fixed point on xi
  Collocation,       ///< fourth-order adaptive collocation of the continuous problem
};

template <>
struct EnumNames<Method> {
  static constexpr std::string_view what = "method";
  static constexpr std::array<std::pair<Method, std::string_view>, 5> names{{
      {Method::Auto, "auto"},
      {Method::Shooting, "shooting"},
      {Method::MultipleShooting, "multiple-shooting"},
      {Method::TwoLevel, "two-level"},
      {Method::Collocation, "collocation"},
  }};
};

/// How shooting (and collocation, for its start) reaches a problem that fails from the guess:
/// not at all, by continuation in the horizon T, or in lambda (from lambda_start).
enum class Continuation { None, T, Lambda };

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
