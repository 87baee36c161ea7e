#pragma once
// The library's one JSON helper kit (layer "api"), used by the result files (result_file.hpp) and
// the CLI's problem files: reading JSON text and files with errors that name the file and the
// flag, reading typed values out of a document, and describing values in messages.
// Messages never dump input: a string is quoted, escaped and cut (quote_input, at most 60
// characters), a container is described by its kind and size, a list of numbers is cut to about
// 60 characters (excerpt).

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace cartan::io {

/// Parses `text` as JSON. Throws std::invalid_argument starting with `what` when it is not valid
/// JSON, holds a number beyond the range of double (e.g. 1e400), or repeats a key in an object
/// (which of two values was meant is ambiguous). The only parser of the CLI's input files and of result files.
nlohmann::json parse_json(const std::string& text, const std::string& what);

/// Parses the JSON file at `path` (parse_json). Throws std::invalid_argument starting with `what` (e.g.
/// "cartan solve: --problem") when the file cannot be read or is not valid JSON.
nlohmann::json read_json_file(const std::string& path, const std::string& what);

/// A short description of a JSON value for messages: a number printed, a string quoted, escaped
/// and cut (quote_input), a container by kind and size ("(an array of 3 entries)", "(an object
/// with 2 keys)"), never dumped: a hostile document may be huge or deeply nested.
std::string describe(const nlohmann::json& value);


/// Parses "x,y,z" into numbers; throws std::invalid_argument "<where>: <name> = ..." on a bad entry.
std::vector<double> parse_list(const std::string& text, const std::string& name, std::string_view where = "cartan solve");

// Typed values of a document. Each throws std::invalid_argument "<where>: <name> = <describe(value)>
// <problem>" when the value has the wrong type.

double json_number(const nlohmann::json& value, std::string_view where, const std::string& name);
/// An integral number within +-2e9.
int json_integer(const nlohmann::json& value, std::string_view where, const std::string& name);
std::string json_text(const nlohmann::json& value, std::string_view where, const std::string& name);
/// A list of finite numbers: an array of numbers, an array of rows (arrays of numbers of one
/// length: a matrix, read row-major), or a string "x,y,z" (parse_list). Entries are named
/// name[i] or name[i][j] in messages.
std::vector<double> json_numbers(const nlohmann::json& value, std::string_view where, const std::string& name);

/// `j[key]`; throws "<where>: <key> = (missing) is required in <what>" when absent.
const nlohmann::json& require_key(const nlohmann::json& j, const std::string& key, std::string_view where,
                                  std::string_view what);

}  // namespace cartan::io
