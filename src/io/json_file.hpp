#pragma once
// Reading a JSON file of a run or comparison directory: a missing, truncated or edited file is an
// InputError naming the file and where parsing stopped (exit 2), never nlohmann's raw
// "[json.exception.parse_error.101] ..." without a file name. A value is taken only through a
// check of its type (json_field, json_optional, json_array, json_object): an edited value is an
// InputError naming the file, the key and the value, never "[json.exception.type_error.302]".
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace iwb::io {

// The parsed file; InputError "<file>: missing ..." or "<file>: not valid JSON ...".
nlohmann::json read_json_file(const std::filesystem::path& path);

// The value at `pointer` (e.g. "/scene/text") as T (std::string, double, int, bool); InputError
// naming the file and the key when it is missing ("<file>: missing or malformed field '/p'") or of
// another type ("<file>: key '/p' = "x": should be a number").
template <class T>
T json_field(const nlohmann::json& j, const std::string& pointer,
             const std::filesystem::path& file);

// The same for a value that may be absent: nullopt when missing or null; InputError when of
// another type.
template <class T>
std::optional<T> json_optional(const nlohmann::json& j, const std::string& pointer,
                               const std::filesystem::path& file);

// The array (object) at `pointer`, to iterate; InputError as json_field's.
const nlohmann::json& json_array(const nlohmann::json& j, const std::string& pointer,
                                 const std::filesystem::path& file);
const nlohmann::json& json_object(const nlohmann::json& j, const std::string& pointer,
                                  const std::filesystem::path& file);

}  // namespace iwb::io
