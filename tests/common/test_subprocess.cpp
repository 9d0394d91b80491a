// External programs: lines arrive as printed, exit codes are reported, a callback can stop one.
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>

#include "common/subprocess.hpp"

using namespace iwb;

TEST_CASE("lines and exit code of a program", "[common]") {
  std::vector<std::string> lines;
  const auto r =
      run_process({"sh", "-c", "echo one; echo two >&2; exit 3"},
                  std::filesystem::temp_directory_path(), [&lines](const std::string& l) {
                    lines.push_back(l);
                    return true;
                  });
  CHECK(r.exit_code == 3);
  CHECK_FALSE(r.stopped);
  CHECK(lines == std::vector<std::string>{"one", "two"});
}

TEST_CASE("a callback stops a running program and its children at once", "[common]") {
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_process({"sh", "-c", "echo start; sleep 30 & sleep 30; echo never"},
                             std::filesystem::temp_directory_path(),
                             [](const std::string& l) { return l != "start"; });
  CHECK(r.stopped);
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10));
}

TEST_CASE("a program that cannot start says so", "[common]") {
  std::string last;
  const auto r = run_process({"no-such-program-iwb"}, std::filesystem::temp_directory_path(),
                             [&last](const std::string& l) {
                               last = l;
                               return true;
                             });
  CHECK(r.exit_code == 127);
  CHECK_THAT(last, Catch::Contains("cannot start no-such-program-iwb"));
}
