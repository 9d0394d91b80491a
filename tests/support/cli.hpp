#pragma once
// The iwb binary as a user runs it, and a directory's files: for tests that assert an exit code,
// a message and that nothing was written or replaced.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/subprocess.hpp"
#include "io/run_directory.hpp"

namespace iwb::test {

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr, merged
};

inline CliRun run_iwb(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {IWB_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  std::string output;
  const auto r =
      run_process(argv, std::filesystem::current_path(), [&output](const std::string& line) {
        output += line + "\n";
        return true;
      });
  return {r.exit_code, output};
}

// Every regular file under `dir` (relative path -> content); empty when dir does not exist.
inline std::map<std::string, std::string> files_under(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  if (!std::filesystem::exists(dir)) return files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      files[std::filesystem::relative(e.path(), dir).string()] = io::read_file(e.path());
  return files;
}

// A fresh copy of `from` at `to` (removed first).
inline void fresh_copy(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::filesystem::remove_all(to);
  std::filesystem::create_directories(to.parent_path());
  std::filesystem::copy(from, to, std::filesystem::copy_options::recursive);
}

}  // namespace iwb::test
