#pragma once
// What the study tests check alike (tests/studies/): every case's run directory completed, the
// page inlines every figure, and the last value of a history column.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "studies/study.hpp"

namespace iwb::test {

// Runs `study` into `dir` (emptied first) and checks its cases and page; returns study.json.
inline nlohmann::json run_study_checked(const studies::StudyDefinition& study,
                                        const std::filesystem::path& dir) {
  std::filesystem::remove_all(dir);
  REQUIRE(studies::run_study(study, {dir, false, "test", nullptr}) == 0);
  for (const auto& c : study.cases) {
    INFO(c.name);
    CHECK(io::read_json_file(dir / c.name / "manifest.json")["status"] == "complete");
  }
  const std::string html = io::read_file(dir / (study.name + ".html"));
  std::size_t svgs = 0;
  for (auto p = html.find("<svg"); p != std::string::npos; p = html.find("<svg", p + 1)) ++svgs;
  CHECK(svgs == study.figures.size());
  return io::read_json_file(dir / "study.json");
}

// The last row's value of `column` in a run's history.csv.
inline double last_history_value(const std::filesystem::path& run, const std::string& column) {
  return io::read_csv_table(run / "history.csv").values(column).back();
}

}  // namespace iwb::test
