#include "io/run_directory.hpp"

#include <fmt/chrono.h>
#include <fmt/core.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"

namespace iwb::io {

namespace fs = std::filesystem;

void write_atomically(const fs::path& path, const std::string& content) {
  const fs::path tmp = path.string() + fmt::format(".tmp{}", ::getpid());
  bool written = false;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("{}: cannot write", tmp.string()));
    out << content;
    out.flush();
    written = bool(out);
  }
  std::error_code error;  // no temporary file is left behind: a full disk, a directory in the way
  if (written) fs::rename(tmp, path, error);
  if (!written || error) fs::remove(tmp);
  if (!written)
    throw std::runtime_error(fmt::format("{}: write failed (disk full?)", tmp.string()));
  if (error)
    throw fs::filesystem_error(fmt::format("{}: cannot replace", path.string()), tmp, path, error);
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot read", path.string()));
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string sha256_hex(const std::string& bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr);
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

std::string utc_timestamp() {
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::chrono::system_clock::now()));
}

void require_new_run_directory(const fs::path& dir, const OutputKind& kind, bool force) {
  require_output_directory(dir, kind, force);
  if (!force && fs::exists(dir / "manifest.json"))
    throw InputError(
        fmt::format("{}: holds an earlier run (manifest.json); choose another --out "
                    "or pass --force to replace it",
                    dir.string()));
}

std::vector<std::string> prepare_run_directory(const fs::path& dir, const OutputKind& kind,
                                               bool force) {
  require_new_run_directory(dir, kind, force);
  // Replaced, not overwritten: files the new run does not write again (a snapshot at a step it
  // never reaches) would otherwise pass for its own. Only the files the ledger lists go.
  return claim_output_directory(dir, kind, force);
}

namespace {

// The path without its spelling: absolute, links resolved, no "." or trailing slash.
fs::path spelling_free(const fs::path& p) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(p, ec);
  return ec ? fs::absolute(p).lexically_normal() : canonical;
}

std::string repeated_directory(const std::string& command, const fs::path& first,
                               const DirectoryRole& first_role, const fs::path& again,
                               const DirectoryRole& role) {
  const std::string given = &first_role == &role
                                ? fmt::format("twice to {} ({})", role.task, role.option)
                                : fmt::format("both to {} ({}) and to {} ({})", first_role.task,
                                              first_role.option, role.task, role.option);
  return fmt::format("{}: {} is given {}{}", command, first.string(), given,
                     again == first ? "" : ", the second time as " + again.string());
}

}  // namespace

void refuse_repeated_directories(const std::string& command,
                                 const std::vector<DirectoryRole>& roles) {
  struct Seen {
    fs::path canonical;
    const fs::path& given;
    const DirectoryRole& role;
  };
  std::vector<Seen> seen;
  for (const auto& role : roles)
    for (const auto& dir : role.dirs) {
      const fs::path canonical = spelling_free(dir);
      for (const auto& s : seen)
        if (s.canonical == canonical)
          throw InputError(repeated_directory(command, s.given, s.role, dir, role));
      seen.push_back({canonical, dir, role});
    }
}

void write_manifest(const fs::path& dir, const nlohmann::json& manifest) {
  write_atomically(dir / "manifest.json", manifest.dump(2) + "\n");
  record_written_files(dir);
}

}  // namespace iwb::io
