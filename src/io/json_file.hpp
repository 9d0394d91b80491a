#pragma once
// Reading a JSON file of a run or comparison directory: a missing, truncated or edited file is an
// InputError naming the file and where parsing stopped, never nlohmann's raw
// "[json.exception.parse_error.101] ..." without a file name.
#include <filesystem>
#include <nlohmann/json.hpp>

namespace iwb::io {

nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace iwb::io
