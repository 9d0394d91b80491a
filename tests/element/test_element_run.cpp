// `iwb element`'s run directory (issue 15, finding 6): a path the model cannot follow is refused
// before the directory is touched, and the manifest lists only files that exist.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>

#include "common/errors.hpp"
#include "element/element_run.hpp"
#include "element/element_test_file.hpp"
#include "io/csv_table.hpp"
#include "io/output_directory.hpp"
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
    if (e.path().filename() != "manifest.json" && e.path().filename() != io::kLedgerFileName)
      present.push_back(e.path().filename().string());
  std::sort(listed.begin(), listed.end());
  std::sort(present.begin(), present.end());
  CHECK(listed == present);
  CHECK(listed == std::vector<std::string>{"history.csv"});
}

// The plane of an interface has no preferred direction for hvwe (its rate is isotropic in the
// plane, seed 5.3), so the same test sheared in y gives in tau_y what it gives in tau_x in x, and
// tau_over_sigma_n, the friction along the path's direction, is the same column in both.
TEST_CASE("element: tau_over_sigma_n is the friction along the path's direction, x or y", "[io]") {
  const auto text = [](const std::string& direction) {
    return "model = { name = \"hvwe\", parameters = \"data/params/table_5_1_evaluation.toml\" }\n"
           "initial = { sigma_n_kPa = 100, e0 = 0.7 }\nboundary = { type = \"CNL\" }\n"
           "path = { kind = \"monotonic\", gamma = 0.1, increments = 50, direction = \"" +
           direction + "\" }\n";
  };
  const auto root = fs::path(IWB_TEST_RUNS_DIR) / "element" / "direction";
  run(text("x"), root / "x");
  run(text("y"), root / "y");
  const auto x = io::read_csv_table(root / "x" / "history.csv");
  const auto y = io::read_csv_table(root / "y" / "history.csv");
  const auto x_tau = x.values("tau_x_kPa"), x_ratio = x.values("tau_over_sigma_n");
  const auto y_tau = y.values("tau_y_kPa"), y_ratio = y.values("tau_over_sigma_n");
  const auto y_sigma = y.values("sigma_n_kPa");
  REQUIRE(x_tau.size() == 51);
  REQUIRE(y_tau.size() == 51);
  for (std::size_t i = 0; i < x_tau.size(); ++i) {
    INFO("row " << i);
    CHECK(y_tau[i] == Approx(x_tau[i]).margin(1e-9));
    CHECK(y_ratio[i] == Approx(y_tau[i] / y_sigma[i]).margin(1e-12));
    CHECK(y_ratio[i] == Approx(x_ratio[i]).margin(1e-12));
  }
  CHECK(y_ratio.back() > 0.5);  // sheared: a friction, not the cross component's 0
}
