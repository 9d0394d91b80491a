#pragma once
// A scene or test file with one value changed: the first occurrence of `from`, which must be there
// (a test that silently edits nothing would test the unedited file).
#include <catch2/catch.hpp>
#include <string>

namespace iwb::test {

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  REQUIRE(p != std::string::npos);
  return text.replace(p, from.size(), to);
}

}  // namespace iwb::test
