// The main job on the smoke scene (real LIGGGHTS run, replay through hvwe, report): the report
// exists, is self-contained and holds its eight figures, drawn by gnuplot as SVG and PNG: four of
// the comparison and four of the band from the coarse-grained fields (issue 21; the smoke run has
// three snapshots, so two band maps).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <regex>

#include "io/run_directory.hpp"

namespace fs = std::filesystem;

TEST_CASE("iwb validate on the smoke scene writes a self-contained report with its figures",
          "[comparison][liggghts]") {
  const fs::path out = fs::path(IWB_TEST_RUNS_DIR) / "validate-smoke";
  const std::string cmd = std::string(IWB_BINARY) +
                          " validate --scene smoke --np 1 --force --out " + out.string() + " > " +
                          (out.string() + ".log") + " 2>&1";
  fs::create_directories(out.parent_path());
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string html = iwb::io::read_file(out / "report.html");
  // eight figures inline, each an SVG with drawn paths
  std::size_t svgs = 0;
  for (auto p = html.find("<svg"); p != std::string::npos; p = html.find("<svg", p + 1)) ++svgs;
  CHECK(svgs == 8);
  CHECK(html.find("<path") != std::string::npos);
  CHECK(html.find("RMSE tau") != std::string::npos);  // the metrics table
  // nothing to fetch: no scripts, no stylesheets, no images or links to load (the SVG
  // namespace URIs are names, not requests)
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("<link") == std::string::npos);
  CHECK(html.find("<img") == std::string::npos);
  CHECK_FALSE(std::regex_search(html, std::regex(R"re((src|href)\s*=\s*"(https?:)?//)re")));
  // the same figures as PNG and SVG beside the HTML, with their data and scripts
  int pngs = 0;
  for (const auto& e : fs::recursive_directory_iterator(out / "report_files"))
    if (e.path().extension() == ".png") {
      ++pngs;
      CHECK(fs::file_size(e.path()) > 10000);  // a blank 900x560 PNG compresses to ~3 kB
      CHECK(fs::exists(fs::path(e.path()).replace_extension(".csv")));
      CHECK(fs::exists(fs::path(e.path()).replace_extension(".gp")));
    }
  CHECK(pngs == 8);
  // the smoke scene has the default scene's grains: the replay uses the set calibrated on them
  CHECK(
      iwb::io::read_file(out / "compare-hvwe" / "manifest.json").find("dem_default_grains.toml") !=
      std::string::npos);
}
