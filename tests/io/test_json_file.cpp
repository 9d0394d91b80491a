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

TEST_CASE("a value of another type is an input error naming the file, the key and the value",
          "[io]") {
  const fs::path file = "calibration.json";  // only named in the messages
  const auto j = nlohmann::json::parse(
      R"({"kind": "calibration", "n": 2, "x": 2.5, "ok": true, "s": null,
          "parameters": [{"key": "phi_c_deg", "sigma": "0.08"}], "runs": "all"})");
  CHECK(io::json_field<std::string>(j, "/kind", file) == "calibration");
  CHECK(io::json_field<int>(j, "/n", file) == 2);
  CHECK(io::json_field<double>(j, "/n", file) == 2.0);
  CHECK(io::json_field<bool>(j, "/ok", file));
  CHECK_THROWS_WITH(io::json_field<double>(j, "/parameters/0/sigma", file),
                    "calibration.json: key '/parameters/0/sigma' = \"0.08\": should be a number");
  CHECK_THROWS_WITH(io::json_field<int>(j, "/x", file),
                    "calibration.json: key '/x' = 2.5: should be a whole number");
  CHECK_THROWS_WITH(io::json_field<std::string>(j, "/n", file),
                    "calibration.json: key '/n' = 2: should be a string");
  CHECK_THROWS_WITH(io::json_field<double>(j, "/parameters/1/sigma", file),
                    "calibration.json: missing or malformed field '/parameters/1/sigma'");
  CHECK_THROWS_WITH(io::json_array(j, "/runs", file),
                    "calibration.json: key '/runs' = \"all\": should be an array");
  CHECK_THROWS_WITH(io::json_object(j, "/parameters", file),
                    Catch::StartsWith("calibration.json: key '/parameters' = [{") &&
                        Catch::EndsWith(": should be an object"));
  // absent or null: nothing; present: its type checked all the same
  CHECK_FALSE(io::json_optional<double>(j, "/s", file).has_value());
  CHECK_FALSE(io::json_optional<double>(j, "/none", file).has_value());
  CHECK_FALSE(io::json_optional<double>(j, "/kind/deeper", file).has_value());
  CHECK_THROWS_WITH(io::json_optional<double>(j, "/kind", file),
                    "calibration.json: key '/kind' = \"calibration\": should be a number");
  CHECK_THROWS_AS(io::json_field<double>(j, "/parameters/0/sigma", file), InputError);
}
