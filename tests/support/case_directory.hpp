#pragma once
// A scratch directory of the running test case: ctest runs every case in a process of its own and
// two at a time, so cases of one file that clear "their" directory must not share it.
#include <catch2/catch.hpp>
#include <cctype>
#include <filesystem>
#include <string>

namespace iwb::test {

inline std::filesystem::path case_directory(const std::filesystem::path& under) {
  std::string name;
  for (char c : Catch::getResultCapture().getCurrentTestName()) {
    if (name.size() >= 60) break;
    name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  }
  return under / name;
}

}  // namespace iwb::test
