#include "json_io.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace cartan::cli {

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  if (std::filesystem::is_directory(path)) throw std::invalid_argument(what + " = " + path + " is a directory");
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(what + " = " + path + " cannot be opened");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(what + " = " + path + " is not valid JSON: " + e.what());
  }
}

void write_json(const nlohmann::json& value, const std::string& path, const std::string& what) {
  if (path.empty()) {
    std::cout << value.dump() << '\n';
    return;
  }
  std::ofstream out(path);
  if (!out) throw std::invalid_argument(what + " = " + path + " cannot be written");
  out << value.dump() << '\n';
  if (!out) throw std::invalid_argument(what + " = " + path + " could not be written completely");
}

}  // namespace cartan::cli
