#pragma once
// Run directories (CONVENTIONS.md "Results"): a manifest.json that says what ran and how it
// ended, CSV files whose first line is the header. Files are written to a temporary name and
// renamed, so a reader never sees half a file; the manifest is written when a run starts
// (status "running") and again when it ends.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/output_directory.hpp"

namespace iwb::io {

void write_atomically(const std::filesystem::path& path, const std::string& content);
std::string read_file(const std::filesystem::path& path);
std::string sha256_hex(const std::string& bytes);
std::string utc_timestamp();  // ISO 8601, seconds

// Prepares `dir` for a new run of `kind` (output_directory.hpp): claims it; refuses (InputError)
// to overwrite a directory that holds a manifest unless `force`; with `force` the files the
// earlier run wrote are removed first, so that none passes for the new one's, and no other file
// (nor the lock file, DirectoryLock, held by the caller). Returns the files kept.
std::vector<std::string> prepare_run_directory(const std::filesystem::path& dir,
                                               const OutputKind& kind, bool force);
// prepare_run_directory's refusals alone, writing nothing, for a command that prepares several
// directories and checks them all before it writes any.
void require_new_run_directory(const std::filesystem::path& dir, const OutputKind& kind,
                               bool force);

// Input directories a command takes in one role: `dirs`, given to `task` ("fit") by `option`.
struct DirectoryRole {
  const std::vector<std::filesystem::path>& dirs;
  std::string task, option;
};
// Refuses (InputError naming `command`, the directory and its roles) a directory given twice,
// in one role or in two: compared as std::filesystem::weakly_canonical, so that run, run/, ./run
// and a link to it are the same.
void refuse_repeated_directories(const std::string& command,
                                 const std::vector<DirectoryRole>& roles);

// Writes the manifest and brings the directory's ledger of written files up to date.
void write_manifest(const std::filesystem::path& dir, const nlohmann::json& manifest);

}  // namespace iwb::io
