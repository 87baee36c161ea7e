#pragma once
// Reading and writing the CLI's JSON files with errors that name the file and the flag.

#include <nlohmann/json.hpp>
#include <string>

namespace cartan::cli {

/// Parses `text` as JSON. Throws std::invalid_argument starting with `what` when it is not valid
/// JSON, holds a number beyond the range of double (e.g. 1e400), or repeats a key in an object
/// (which of two values was meant is ambiguous). The only parser of the CLI's input files.
nlohmann::json parse_json(const std::string& text, const std::string& what);

/// Parses the JSON file at `path` (parse_json). Throws std::invalid_argument starting with `what` (e.g.
/// "cartan solve: --problem") when the file cannot be read or is not valid JSON.
nlohmann::json read_json_file(const std::string& path, const std::string& what);

/// Writes `value` as one line to `path`, or to stdout when `path` is empty. Throws
/// std::invalid_argument starting with `what` when the file cannot be written.
void write_json(const nlohmann::json& value, const std::string& path, const std::string& what);

}  // namespace cartan::cli
