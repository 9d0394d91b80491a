#include "io/output_directory.hpp"

#include <fmt/core.h>

#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>

#include "common/errors.hpp"
#include "io/directory_lock.hpp"
#include "io/run_directory.hpp"

namespace iwb::io {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Files that are never anyone's output: the ledger itself at the top, lock files, and the
// temporary names of write_atomically and StagedDirectory (NAME.tmpPID), gone when they finish.
bool is_bookkeeping(const fs::path& relative) {
  static const std::regex temporary(R"(.*\.tmp[0-9]+$)");
  const std::string name = relative.filename().string();
  return relative == kLedgerFileName || name == kLockFileName || std::regex_match(name, temporary);
}

// Every file under `dir` (not following links), by path relative to it, with its mtime.
std::map<std::string, fs::file_time_type> files_under(const fs::path& dir) {
  std::map<std::string, fs::file_time_type> files;
  if (!fs::is_directory(dir)) return files;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator();
       ++it) {
    const fs::path relative = it->path().lexically_relative(dir);  // no system call per file
    if (is_bookkeeping(relative)) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_directory() && !it->is_symlink()) continue;
    std::error_code ignored;
    files[relative.generic_string()] =
        fs::symlink_status(it->path()).type() == fs::file_type::symlink
            ? fs::file_time_type{}
            : it->last_write_time(ignored);
  }
  return files;
}

struct Ledger {
  std::string kind;
  std::set<std::string> written;
};

// A ledger's entry names a file inside its directory: never absolute, never through "..", so that
// an edited ledger cannot make --force remove a file elsewhere.
bool inside(const std::string& entry) {
  const fs::path p(entry);
  if (entry.empty() || p.is_absolute()) return false;
  for (const auto& part : p)
    if (part == "..") return false;
  return true;
}

std::optional<Ledger> read_ledger(const fs::path& dir) {
  const fs::path file = dir / kLedgerFileName;
  if (!fs::exists(file)) return std::nullopt;
  try {
    const json j = json::parse(read_file(file));
    Ledger l{j.at("kind").get<std::string>(), {}};
    for (const auto& f : j.at("written")) {
      const auto entry = f.get<std::string>();
      if (!inside(entry))
        throw InputError(fmt::format(
            "{}: entry \"{}\" lies outside {}; the ledger lists only the files the workbench "
            "wrote inside its directory: restore it, or choose another --out",
            file.string(), entry, dir.string()));
      l.written.insert(entry);
    }
    return l;
  } catch (const json::exception& e) {
    throw InputError(fmt::format(
        "{}: not a ledger of the workbench ({}); it says which files --force may remove: "
        "restore it, or choose another --out",
        file.string(), e.what()));
  }
}

void write_ledger(const fs::path& dir, const Ledger& l) {
  json j = {
      {"kind", l.kind},
      {"about", "the files iwb wrote into this directory: --force removes these and no other"},
      {"written", l.written}};
  write_atomically(dir / kLedgerFileName, j.dump(1) + "\n");
}

// The directories this process claimed, each with the files that were there at the claim and not
// in its ledger (the user's, or a killed run's), as they were then.
struct Claims {
  std::mutex mutex;
  std::map<std::string, std::map<std::string, fs::file_time_type>> foreign;
};
Claims& claims() {
  static Claims c;
  return c;
}
std::string key_of(const fs::path& dir) {
  return fs::weakly_canonical(fs::absolute(dir)).string();
}

bool legacy_of(const fs::path& dir, const OutputKind& k) {
  const fs::path marker = dir / k.marker;
  if (!fs::is_regular_file(marker)) return false;
  if (k.marker != "manifest.json") return true;
  try {
    return json::parse(read_file(marker)).value("kind", "") == k.kind;
  } catch (const json::exception&) {
    return false;
  }
}

std::string kind_words(const std::string& kind) {
  return fmt::format("an output of the workbench's '{}'", kind);
}

// Removes `file` and then each parent folder up to `dir` (excluded) that it leaves empty.
void remove_with_empty_parents(const fs::path& dir, const fs::path& file) {
  std::error_code ignored;
  fs::remove(file, ignored);
  for (fs::path p = file.parent_path(); p != dir && p.string().size() > dir.string().size();
       p = p.parent_path())
    if (!fs::is_directory(p) || !fs::is_empty(p) || !fs::remove(p, ignored)) break;
}

}  // namespace

void remove_written_files(const fs::path& dir, const std::vector<std::string>& replacing) {
  if (!fs::exists(dir)) return;
  auto ledger = read_ledger(dir);
  const auto present = files_under(dir);
  if (!ledger && !present.empty())
    throw InputError(fmt::format(
        "{}: holds '{}', which the workbench did not write ({} is missing); move it away or "
        "choose another output",
        dir.string(), present.begin()->first, kLedgerFileName));
  if (!ledger) return;
  for (const auto& f : replacing)
    if (present.count(f) && !ledger->written.count(f))
      throw InputError(
          fmt::format("{}: '{}' was not written by the workbench; move it away", dir.string(), f));
  for (const auto& f : ledger->written) remove_with_empty_parents(dir, dir / f);
  ledger->written.clear();
  write_ledger(dir, *ledger);
}

void adopt_written_files(const fs::path& dir, const std::string& kind,
                         const std::vector<std::string>& files) {
  Ledger ledger = read_ledger(dir).value_or(Ledger{kind, {}});
  ledger.written.insert(files.begin(), files.end());
  write_ledger(dir, ledger);
}

void require_output_directory(const fs::path& dir, const OutputKind& k, bool replace) {
  if (!fs::exists(dir)) return;
  if (!fs::is_directory(dir))
    throw InputError(fmt::format("{}: is a file, not a directory; give a directory to write into",
                                 dir.string()));
  DirectoryLock::require_free(dir);  // another iwb at work there is the first thing to say
  if (const auto ledger = read_ledger(dir)) {
    bool accepted = ledger->kind == k.kind;
    for (const auto& a : k.accepts) accepted = accepted || ledger->kind == a.kind;
    if (!accepted)
      throw InputError(fmt::format("{}: holds {}, not of '{}' ({}); choose another directory",
                                   dir.string(), kind_words(ledger->kind), k.kind,
                                   kLedgerFileName));
    return;
  }
  const auto files = files_under(dir);
  if (files.empty()) return;
  bool legacy = legacy_of(dir, k);
  for (const auto& a : k.accepts) legacy = legacy || legacy_of(dir, a);
  if (legacy && replace)
    throw InputError(fmt::format(
        "{}: written by an iwb that did not record its files ({} is missing), so --force "
        "cannot tell its files from yours; remove the directory yourself or choose another",
        dir.string(), kLedgerFileName));
  if (!legacy)
    throw InputError(fmt::format(
        "{}: is not empty and is not {} (it holds '{}', which the workbench did not write); "
        "choose a new or empty directory",
        dir.string(), kind_words(k.kind), files.begin()->first));
}

std::vector<std::string> claim_output_directory(const fs::path& dir, const OutputKind& k,
                                                bool replace) {
  require_output_directory(dir, k, replace);
  fs::create_directories(dir);
  bool claimed_before = false;  // by this process: its ledger is brought up to date, and what was
  {                             // foreign at the first claim stays foreign
    std::lock_guard guard(claims().mutex);
    claimed_before = claims().foreign.count(key_of(dir)) > 0;
  }
  if (claimed_before) record_written_files(dir);
  Ledger ledger = read_ledger(dir).value_or(Ledger{k.kind, {}});
  auto present = files_under(dir);
  if (replace) {
    for (const auto& f : ledger.written) remove_with_empty_parents(dir, dir / f);
    ledger.written.clear();
    present = files_under(dir);
  }
  for (auto it = present.begin(); it != present.end();)
    it = ledger.written.count(it->first) ? present.erase(it) : std::next(it);
  write_ledger(dir, ledger);
  std::vector<std::string> kept;
  for (const auto& [f, t] : present) kept.push_back(f);
  std::lock_guard guard(claims().mutex);
  if (!claimed_before || replace) claims().foreign[key_of(dir)] = std::move(present);
  return replace ? kept : std::vector<std::string>{};
}

void record_written_files(const fs::path& dir) {
  std::map<std::string, fs::file_time_type> foreign;
  {
    std::lock_guard guard(claims().mutex);
    const auto it = claims().foreign.find(key_of(dir));
    if (it == claims().foreign.end()) return;
    foreign = it->second;
  }
  auto ledger = read_ledger(dir);
  if (!ledger) return;  // removed under us: nothing to keep up to date
  Ledger now{ledger->kind, {}};
  for (const auto& [f, t] : files_under(dir)) {
    const auto was = foreign.find(f);
    if (ledger->written.count(f) || was == foreign.end() || was->second != t) now.written.insert(f);
  }
  if (now.written != ledger->written) write_ledger(dir, now);
}

void release_claimed_directories() {
  std::vector<std::string> dirs;
  {
    std::lock_guard guard(claims().mutex);
    for (const auto& [d, f] : claims().foreign) dirs.push_back(d);
  }
  for (const auto& d : dirs) {
    try {
      record_written_files(d);
    } catch (const std::exception&) {  // a directory removed since: nothing of ours is left there
    }
  }
  std::lock_guard guard(claims().mutex);
  for (const auto& d : dirs) claims().foreign.erase(d);
}

}  // namespace iwb::io
