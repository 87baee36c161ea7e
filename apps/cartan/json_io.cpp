#include "json_io.hpp"

#include <cstdio>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace cartan::cli {

nlohmann::json parse_json(const std::string& text, const std::string& what) {
  std::vector<std::set<std::string>> keys_of_open_objects;
  const nlohmann::json::parser_callback_t reject_duplicate_keys =
      [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (event == Event::object_start) keys_of_open_objects.emplace_back();
        if (event == Event::object_end) keys_of_open_objects.pop_back();
        if (event == Event::key && !keys_of_open_objects.back().insert(parsed.get<std::string>()).second) {
          throw std::invalid_argument(what + " repeats the key " + parsed.dump() + " (give each key once)");
        }
        return true;
      };
  try {
    return nlohmann::json::parse(text, reject_duplicate_keys);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(what + " is not valid JSON: " + e.what());
  } catch (const nlohmann::json::out_of_range& e) {  // 406: a number beyond double, e.g. 1e400
    throw std::invalid_argument(what + " has a number out of range: " + e.what());
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

void write_json(const nlohmann::json& value, const std::string& path, const std::string& what) {
  if (path.empty()) {
    std::cout << value.dump() << '\n';
    return;
  }
  // Written beside the target and renamed into place, so that an interrupted run never leaves
  // a half-written file under the requested name.
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial);
    if (!out) throw std::invalid_argument(what + " = " + path + " cannot be written");
    out << value.dump() << '\n';
    if (!out) {
      std::remove(partial.c_str());
      throw std::invalid_argument(what + " = " + path + " could not be written completely");
    }
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    std::remove(partial.c_str());
    throw std::invalid_argument(what + " = " + path + " cannot be written");
  }
}

}  // namespace cartan::cli
