#pragma once
// The orders of the discrete schemes and of results, the vocabulary of both stacks (kernels/lie_group/,
// kernels/manifold/), the CLI and Python, defined and checked once: a scheme is of order 1 (the paper's
// disc-* equations) or 2 (our symmetric composition of them); a result's order is its scheme's, or
// 4 for collocation (the continuous system by fourth-order Lobatto IIIA collocation).

#include <string_view>

namespace cartan {

enum class SchemeOrder { First = 1, Second = 2 };

/// The order a collocation result reports (numerics/collocation.hpp), beside the schemes' 1 and 2.
inline constexpr int kCollocationOrder = 4;

/// 1 or 2: the schemes' orders.
constexpr bool is_scheme_order(double order) { return order == 1 || order == 2; }
/// A result's order: a scheme's, or collocation's.
constexpr bool is_result_order(double order) { return is_scheme_order(order) || order == kCollocationOrder; }
/// What the checks below say of any other number.
inline constexpr const char* kSchemeOrderRule = "must be 1 or 2";
inline constexpr const char* kResultOrderRule = "must be 1 or 2 (the schemes) or 4 (collocation)";

/// Throws std::invalid_argument "<where>: order = <k> must be 1 or 2" unless `order` is First or Second.
void require_scheme_order(SchemeOrder order, std::string_view where);
/// The order a user wrote (1 or 2) as a SchemeOrder; throws as require_scheme_order otherwise.
SchemeOrder scheme_order(int order, std::string_view where);
/// Throws std::invalid_argument "<where>: order = <k> must be 1 or 2 (the schemes) or 4
/// (collocation)" unless `order` is a result's order.
void require_result_order(int order, std::string_view where);

}  // namespace cartan
