#pragma once
// Shared helpers for cartan's tests: the installed ones (cartan/testing/support.hpp: seeded random
// algebra elements, EXPECT_NEAR_MATRIX) and expect_invalid.

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cartan/testing/support.hpp"

namespace cartan::testing {

/// Runs `call`, expecting std::invalid_argument whose message contains every fragment (the
/// bad value's name and value, STYLE.md "errors name the value").
template <class F>
void expect_invalid(const F& call, std::initializer_list<std::string_view> fragments) {
  try {
    call();
    ADD_FAILURE() << "no std::invalid_argument thrown";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    for (std::string_view fragment : fragments) EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

template <class F>
void expect_invalid(const F& call, std::string_view fragment) {
  expect_invalid(call, {fragment});
}

}  // namespace cartan::testing

