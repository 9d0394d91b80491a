#pragma once
// Reading a JSON file of a run or comparison directory: a missing, truncated or edited file is an
// InputError naming the file and where parsing stopped (exit 2), never nlohmann's raw
// "[json.exception.parse_error.101] ..." without a file name.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace iwb::io {

// The parsed file; InputError "<file>: missing ..." or "<file>: not valid JSON ...".
nlohmann::json read_json_file(const std::filesystem::path& path);

// The value at `pointer` (e.g. "/scene/text") as T; InputError naming the file and the key when
// it is missing or of another type.
template <class T>
T json_field(const nlohmann::json& j, const std::string& pointer,
             const std::filesystem::path& file);

}  // namespace iwb::io
