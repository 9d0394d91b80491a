// A run directory's JSON file read back: missing, truncated or edited files are input errors
// naming the file, never nlohmann's raw "[json.exception...]".
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "io/json_file.hpp"

using namespace iwb;
namespace fs = std::filesystem;

TEST_CASE("a truncated or missing JSON file is an input error naming the file", "[io]") {
  const fs::path dir = fs::path(IWB_TEST_RUNS_DIR) / "json_file";
  fs::create_directories(dir);
  const auto file = dir / "manifest.json";
  std::ofstream(file)
      << R"({"status": "complete", "stages": {"consolidate": {"wall_seconds": 1.5}}})";
  CHECK(io::read_json_file(file)["status"] == "complete");

  std::ofstream(file) << R"({"status": "complete", "stag)";
  CHECK_THROWS_AS(io::read_json_file(file), InputError);
  CHECK_THROWS_WITH(
      io::read_json_file(file),
      Catch::Contains(file.string() +
                      ": not valid JSON (truncated or edited?): parsing stopped at byte") &&
          !Catch::Contains("json.exception"));
  std::ofstream(file) << "";
  CHECK_THROWS_WITH(io::read_json_file(file), Catch::Contains("at byte 0 of 0"));
  CHECK_THROWS_WITH(io::read_json_file(dir / "summary.json"),
                    Catch::Contains("summary.json: missing"));
  CHECK_THROWS_WITH(io::read_json_file(dir), Catch::Contains("json_file: missing"));
}
