#pragma once
// JSON files of run and comparison directories, read so that every failure names the file: a
// missing or truncated manifest.json is bad input (exit 2), not a raw parser message.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace iwb::io {

// The parsed file; InputError "<file>: missing" or "<file>: not valid JSON (<parser's words>)".
nlohmann::json read_json(const std::filesystem::path& file);

// The value at `pointer` (e.g. "/scene/text") as T; InputError naming the file and the key when
// it is missing or of another type.
template <class T>
T json_field(const nlohmann::json& j, const std::string& pointer, const std::filesystem::path& file);

}  // namespace iwb::io
