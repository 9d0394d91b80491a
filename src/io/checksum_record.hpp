#pragma once
// A file's size and sha256 written next to it (<file>.checksum.json, atomically, after the file),
// so that whoever uses the file later can tell it from the one that was written: an engine's
// restart that was truncated or replaced is rebuilt, never used (issue 15, finding 8).
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace iwb::io {

std::filesystem::path checksum_record_path(const std::filesystem::path& file);

// Writes the record of `file` as it is now and returns it ({"file", "size_bytes", "sha256"}).
nlohmann::json write_checksum_record(const std::filesystem::path& file);

// Nothing when `file` is there and matches its record; otherwise why not, in words: the file or
// its record missing, or the size or the hash differing.
std::optional<std::string> checksum_problem(const std::filesystem::path& file);

}  // namespace iwb::io
