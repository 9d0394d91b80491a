// `iwb element`'s run directory (issue 15, finding 6): a path the model cannot follow is refused
// before the directory is touched, and the manifest lists only files that exist.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>

#include "common/errors.hpp"
#include "element/element_run.hpp"
#include "element/element_test_file.hpp"
#include "io/toml_reader.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

std::string hp1d_test(const std::string& direction) {
  return "model = { name = \"hp1d\", parameters = \"data/params/table_5_2_hostun.toml\" }\n"
         "initial = { sigma_n_kPa = 100, e0 = 0.7 }\nboundary = { type = \"CNL\" }\n"
         "path = { kind = \"monotonic\", gamma = 0.1, increments = 100, direction = \"" +
         direction + "\" }\n";
}

element::ElementRunOutcome run(const std::string& text, const fs::path& dir) {
  element::ElementRunOptions opt;
  opt.out = dir;
  opt.force = true;
  opt.input_text = text;
  return element::run_element_to_directory(
      element::parse_element_test(io::parse_toml_text(text, "t.toml"), "t.toml", "."), opt);
}

}  // namespace

TEST_CASE(
    "element: hp1d sheared in y is refused naming file, key and value, before anything is written",
    "[io]") {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "element" / "hp1d_y";
  fs::remove_all(dir);
  CHECK_THROWS_WITH(run(hp1d_test("y"), dir),
                    "t.toml: key 'path.direction' = \"y\": model hp1d has one shear direction; use "
                    "direction = \"x\"");
  CHECK_FALSE(fs::exists(dir));
}

TEST_CASE("element: the manifest lists exactly the files the run directory holds", "[io]") {
  const auto dir = fs::path(IWB_TEST_RUNS_DIR) / "element" / "hp1d_x";
  const auto outcome = run(hp1d_test("x"), dir);
  REQUIRE(outcome.result.complete());
  std::vector<std::string> listed, present;
  for (const auto& f : outcome.manifest["files"]) listed.push_back(f);
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != "manifest.json") present.push_back(e.path().filename().string());
  std::sort(listed.begin(), listed.end());
  std::sort(present.begin(), present.end());
  CHECK(listed == present);
  CHECK(listed == std::vector<std::string>{"history.csv"});
}
