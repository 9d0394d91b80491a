// A file's size and hash recorded next to it: every way the file can differ from what was
// written is told apart, in words.
#include <catch2/catch.hpp>
#include <filesystem>

#include "io/checksum_record.hpp"
#include "io/run_directory.hpp"

using namespace iwb;
namespace fs = std::filesystem;

TEST_CASE("a checksum record tells a missing, truncated or altered file and a missing record",
          "[io]") {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "io" / "checksum";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "consolidated.restart";
  io::write_atomically(file, "0123456789");
  CHECK_THAT(*io::checksum_problem(file), Catch::Contains("has no size and hash record"));
  const auto record = io::write_checksum_record(file);
  CHECK(record["size_bytes"] == 10);
  CHECK_FALSE(io::checksum_problem(file));
  io::write_atomically(file, "01234");
  CHECK_THAT(*io::checksum_problem(file), Catch::Contains("has 5 bytes, its record says 10"));
  io::write_atomically(file, "0123456780");
  CHECK_THAT(*io::checksum_problem(file), Catch::Contains("not the recorded sha256"));
  fs::remove(file);
  CHECK_THAT(*io::checksum_problem(file), Catch::Contains("is missing"));
}
