#include "cartan/api/json_io.hpp"

#include <cmath>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "cartan/errors.hpp"

namespace cartan::io {

namespace {

/// The parser's message cut to 160 characters: it quotes the last token read, which may be huge.
std::string shortened(const std::string& message) {
  constexpr std::size_t kMax = 160;
  return message.size() > kMax ? message.substr(0, kMax) + "..." : message;
}

}  // namespace

nlohmann::json parse_json(const std::string& text, const std::string& what) {
  std::vector<std::set<std::string>> keys_of_open_objects;
  const nlohmann::json::parser_callback_t reject_duplicate_keys =
      [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (event == Event::object_start) keys_of_open_objects.emplace_back();
        if (event == Event::object_end) keys_of_open_objects.pop_back();
        if (event == Event::key && !keys_of_open_objects.back().insert(parsed.get<std::string>()).second) {
          throw std::invalid_argument(what + " repeats the key " + quote_input(parsed.get<std::string>()) +
                                      " (give each key once)");
        }
        return true;
      };
  try {
    return nlohmann::json::parse(text, reject_duplicate_keys);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(what + " is not valid JSON: " + shortened(e.what()));
  } catch (const nlohmann::json::out_of_range& e) {  // 406: a number beyond double, e.g. 1e400
    throw std::invalid_argument(what + " has a number out of range: " + shortened(e.what()));
  }
}

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  if (std::filesystem::is_directory(path)) throw std::invalid_argument(what + " = " + path + " is a directory");
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(what + " = " + path + " cannot be opened");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_json(text.str(), what + " = " + path);
}


std::string describe(const nlohmann::json& value) {
  if (value.is_number()) return format_value(value.get<double>());
  if (value.is_string()) return quote_input(value.get_ref<const std::string&>());
  if (value.is_array()) return "(an array of " + std::to_string(value.size()) + " entries)";
  if (value.is_object()) return "(an object with " + std::to_string(value.size()) + " keys)";
  return std::string("(") + value.type_name() + ")";
}

std::vector<double> parse_list(const std::string& text, const std::string& name, std::string_view where) {
  std::vector<double> out;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    const std::string trimmed = first == std::string::npos ? "" : item.substr(first, last - first + 1);
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(trimmed, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (trimmed.empty() || used != trimmed.size()) {
      throw_invalid(where, name, quote_input(text), "is not a comma-separated list of numbers");
    }
    out.push_back(value);
  }
  if (out.empty()) throw_invalid(where, name, quote_input(text), "is empty");
  return out;
}

double json_number(const nlohmann::json& value, std::string_view where, const std::string& name) {
  if (!value.is_number()) throw_invalid(where, name, describe(value), "must be a number");
  return value.get<double>();
}

int json_integer(const nlohmann::json& value, std::string_view where, const std::string& name) {
  if (!value.is_number()) throw_invalid(where, name, describe(value), "must be an integer");
  const double x = value.get<double>();
  if (!std::isfinite(x) || std::floor(x) != x) throw_invalid(where, name, describe(value), "must be an integer");
  if (std::abs(x) > 2e9) throw_invalid(where, name, describe(value), "is out of range");
  return static_cast<int>(x);
}

std::string json_text(const nlohmann::json& value, std::string_view where, const std::string& name) {
  if (!value.is_string()) throw_invalid(where, name, describe(value), "must be a string");
  return value.get<std::string>();
}

std::vector<double> json_numbers(const nlohmann::json& value, std::string_view where, const std::string& name) {
  if (value.is_string()) return parse_list(value.get<std::string>(), name, where);
  if (!value.is_array()) throw_invalid(where, name, describe(value), "must be a list of numbers");
  const auto entry = [&](const nlohmann::json& x, const std::string& entry_name) {
    if (!x.is_number()) throw_invalid(where, entry_name, describe(x), "must be a number");
    const double number = x.get<double>();
    if (!std::isfinite(number)) throw_invalid(where, entry_name, describe(x), "is not finite");
    return number;
  };
  std::vector<double> out;
  const bool rows = !value.empty() && value[0].is_array();  // a matrix given as rows
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string row_name = name + "[" + std::to_string(i) + "]";
    if (!rows) {
      out.push_back(entry(value[i], row_name));
      continue;
    }
    if (!value[i].is_array() || value[i].size() != value[0].size()) {
      throw_invalid(where, row_name, describe(value[i]),
                    "must be a row of " + std::to_string(value[0].size()) + " numbers, as " + name + "[0]");
    }
    for (std::size_t j = 0; j < value[i].size(); ++j) out.push_back(entry(value[i][j], row_name + "[" + std::to_string(j) + "]"));
  }
  return out;
}

const nlohmann::json& require_key(const nlohmann::json& j, const std::string& key, std::string_view where,
                                  std::string_view what) {
  const auto it = j.find(key);
  if (it == j.end()) throw_invalid(where, key, "(missing)", "is required in " + std::string(what));
  return *it;
}

}  // namespace cartan::io
