#pragma once
// Output directories are the workbench's alone (issue 60): a command writes only into a directory
// that is new, empty or an earlier output of the same kind, and `--force` removes only the files
// the workbench wrote there, never another. What it wrote is kept in the directory's ledger,
// DIR/iwb-written.json ({"kind", "written": [relative paths]}), written when the directory is
// claimed and brought up to date whenever a manifest is written there and when the command ends.
//
// A file counts as written by the workbench when the ledger lists it, when it appeared after the
// claim, or when it was there at the claim and has changed since (a crashed run's file written
// again). A file a user puts into the directory while a command runs there is therefore taken for
// the workbench's; one put there at any other time is not, and survives every `--force`.
#include <filesystem>
#include <string>
#include <vector>

namespace iwb::io {

inline constexpr const char* kLedgerFileName = "iwb-written.json";

// What an output directory may hold: `kind` is written into the ledger and compared with it;
// `accepts` are further kinds whose directories this one may share (plan.json into a tradeoff's
// directory); `marker` is the file that identifies an output of this kind from before the ledger
// (manifest.json, when its "kind" is `kind`, or a file only this kind writes), so that an earlier
// run is resumed or reused. Such a directory cannot be replaced: nothing says which files are ours.
struct OutputKind {
  std::string kind;
  std::string marker = "manifest.json";
  std::vector<OutputKind> accepts = {};
};

// Refuses (InputError, exit 2), writing nothing, a destination that is a file, a non-empty
// directory without a ledger or marker of the kind (naming one of its files), or a ledger of
// another kind; with `replace` (--force) also a directory from before the ledger.
void require_output_directory(const std::filesystem::path& dir, const OutputKind& kind,
                              bool replace);

// require_output_directory, then creates `dir` and its ledger. With `replace`, removes every file
// the ledger lists (and the folders that leaves empty) and returns the files it kept because the
// workbench did not write them; nothing else is removed. The lock file (directory_lock.hpp) stays.
std::vector<std::string> claim_output_directory(const std::filesystem::path& dir,
                                                const OutputKind& kind, bool replace);

// For a directory a command builds whole (StagedDirectory): removes the files dir's ledger lists
// and refuses (InputError, nothing removed) a directory that holds files but no ledger, or one of
// `replacing` that the ledger does not list. Returns nothing; the ledger's list is emptied.
void remove_written_files(const std::filesystem::path& dir,
                          const std::vector<std::string>& replacing);
// Adds `files` (relative to dir) to dir's ledger, which is created of `kind` if there is none.
void adopt_written_files(const std::filesystem::path& dir, const std::string& kind,
                         const std::vector<std::string>& files);

// Brings the ledger of `dir` up to date if this process claimed it (else nothing): called by
// write_manifest, so that a run killed between two manifests loses at most what it wrote since.
void record_written_files(const std::filesystem::path& dir);
// The same for every directory this process claimed, which it then no longer holds: the command
// line calls it when a command ends, whether it succeeded, failed or was interrupted. A file that
// appears in a directory after that is not the workbench's.
void release_claimed_directories();

}  // namespace iwb::io
