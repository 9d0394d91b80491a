#pragma once
// A scene or test file with one value changed: the first occurrence of `from`, which must be there
// (a test that silently edits nothing would test the unedited file).
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "io/run_directory.hpp"

namespace iwb::test {

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  REQUIRE(p != std::string::npos);
  return text.replace(p, from.size(), to);
}

// The same in a file, rewritten in place (atomically).
inline void edit_file(const std::filesystem::path& file, const std::string& from,
                      const std::string& to) {
  io::write_atomically(file, replaced(io::read_file(file), from, to));
}

}  // namespace iwb::test
