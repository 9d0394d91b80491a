#pragma once
// Run directories (CONVENTIONS.md "Results"): a manifest.json that says what ran and how it
// ended, CSV files whose first line is the header. Files are written to a temporary name and
// renamed, so a reader never sees half a file; the manifest is written when a run starts
// (status "running") and again when it ends.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace iwb::io {

void write_atomically(const std::filesystem::path& path, const std::string& content);
std::string read_file(const std::filesystem::path& path);
std::string sha256_hex(const std::string& bytes);
std::string utc_timestamp();  // ISO 8601, seconds

// Prepares `dir` for a new run: creates it; refuses (InputError) to overwrite a directory that
// holds a manifest unless `force`; with `force` such a directory is emptied first, so that no file
// of the earlier run passes for the new one's (but its lock file, DirectoryLock, held by the
// caller).
void prepare_run_directory(const std::filesystem::path& dir, bool force);
// prepare_run_directory's refusal alone, for a command that prepares several directories and
// checks them all before it writes any.
void require_new_run_directory(const std::filesystem::path& dir, bool force);

void write_manifest(const std::filesystem::path& dir, const nlohmann::json& manifest);

}  // namespace iwb::io
