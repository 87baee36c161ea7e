// The checks of cartan/scheme_order.hpp.
#include "cartan/scheme_order.hpp"

#include <string>

#include "cartan/errors.hpp"

namespace cartan {

void require_scheme_order(SchemeOrder order, std::string_view where) {
  const int k = static_cast<int>(order);
  if (!is_scheme_order(k)) throw_invalid(where, "order", std::to_string(k), kSchemeOrderRule);
}

SchemeOrder scheme_order(int order, std::string_view where) {
  if (!is_scheme_order(order)) throw_invalid(where, "order", std::to_string(order), kSchemeOrderRule);
  return static_cast<SchemeOrder>(order);
}

void require_result_order(int order, std::string_view where) {
  if (!is_result_order(order)) throw_invalid(where, "order", std::to_string(order), kResultOrderRule);
}

}  // namespace cartan
