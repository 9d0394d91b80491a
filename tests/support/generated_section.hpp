#pragma once
// A section of a README generated from declarations, between two marker lines: the test holds it
// equal to what the code generates, and rewrites it (atomically) when IWB_README_REGENERATE=1.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "io/run_directory.hpp"

namespace iwb::test {

inline void check_generated_section(const std::string& path, const std::string& begin,
                                    const std::string& end, const std::string& generated,
                                    const std::string& regenerate_tag) {
  std::string text = io::read_file(path);
  const auto b = text.find(begin);
  REQUIRE(b != std::string::npos);
  const auto from = b + begin.size();
  const auto e = text.find(end, from);
  REQUIRE(e != std::string::npos);
  const char* flag = std::getenv("IWB_README_REGENERATE");
  if (flag != nullptr && std::string(flag) == "1") {
    text.replace(from, e - from, generated);
    io::write_atomically(path, text);
    WARN("regenerated the generated section of " << path);
  }
  INFO("regenerate: IWB_README_REGENERATE=1 build/tests/iwb_tests \"" << regenerate_tag << "\"");
  const auto now = text.find(end, from);
  CHECK(text.substr(from, now - from) == generated);
}

}  // namespace iwb::test
