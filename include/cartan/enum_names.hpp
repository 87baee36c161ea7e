#pragma once
// One spelling for every enum that cartan prints or parses (statuses, methods, sides, scheme
// orders, ...), shared by the C++ API, the CLI's flags and JSON, and the Python module.
//
// An enum E opts in by specialising EnumNames<E> next to its definition:
//   template <> struct EnumNames<Side> {
//     static constexpr std::string_view what = "side";
//     static constexpr std::array<std::pair<Side, std::string_view>, 2> names{{{Side::Left, "left"}, ...}};
//   };
// Then to_string(e) prints it and parse_enum<E>(text) reads it back (or throws
// std::invalid_argument listing the accepted words).

#include <array>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cartan/errors.hpp"

namespace cartan {

template <class E>
struct EnumNames;

template <class E>
concept NamedEnum = std::is_enum_v<E> && requires {
  EnumNames<E>::what;
  EnumNames<E>::names;
};

template <NamedEnum E>
constexpr std::string_view to_string(E value) {
  for (const auto& [e, name] : EnumNames<E>::names) {
    if (e == value) return name;
  }
  return "unknown";
}

/// Streams the word (test frameworks and logs print enums this way).
template <NamedEnum E>
std::ostream& operator<<(std::ostream& os, E value) {
  return os << to_string(value);
}

/// Every accepted word, in declaration order.
template <NamedEnum E>
std::vector<std::string> enum_words() {
  std::vector<std::string> words;
  for (const auto& entry : EnumNames<E>::names) words.emplace_back(entry.second);
  return words;
}

/// "a | b | c": the accepted words, for messages and help texts.
template <NamedEnum E>
std::string enum_choices(std::string_view separator = " | ") {
  std::string out;
  for (const auto& entry : EnumNames<E>::names) {
    if (!out.empty()) out += separator;
    out += entry.second;
  }
  return out;
}

/// The value spelled `text`; throws std::invalid_argument("<what> = "text" is not one of: ...").
/// `where` prefixes the message (e.g. "cartan solve").
template <NamedEnum E>
E parse_enum(std::string_view text, std::string_view where = "cartan") {
  for (const auto& [e, name] : EnumNames<E>::names) {
    if (name == text) return e;
  }
  throw std::invalid_argument(std::string(where) + ": " + std::string(EnumNames<E>::what) + " = " +
                              quote_input(text) + " is not one of: " + enum_choices<E>(", "));
}

}  // namespace cartan
