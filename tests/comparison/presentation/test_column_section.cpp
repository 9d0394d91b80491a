// The report's section of a micro-polar column (comparison/presentation/column_section.hpp): the
// column's profiles beside the DEM runs it names, read from their files alone.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "column/column_output.hpp"
#include "comparison/presentation/report.hpp"
#include "io/csv_table.hpp"
#include "io/parameter_file.hpp"

using namespace iwb;

namespace {

namespace fs = std::filesystem;

const fs::path kColumnWork = fs::path(IWB_TEST_RUNS_DIR) / "column_report";
// a committed truth run (R_n 0.5, CNL 50 kPa): its profiles.csv's last window is at 9.6 mm
const fs::path kColumnDemRun = fs::absolute("data/convergence/truth_clamped/runs/s1");

column::ColumnSpec short_column() {
  column::ColumnSpec s;
  const auto tables = io::load_parameter_file("data/params/truth_grains_epsd2.toml");
  s.soil = models::HypoplasticParameters::from(tables.at("hypoplastic"), "truth_grains_epsd2");
  s.elements = 28;
  s.e0 = 0.66;
  s.travel_mm = 2.0;
  s.increments = 50;
  return s;
}

// The points of a figure's CSV curve pair `k` (x_k, y_k), nan padding dropped (read here: the
// table reader refuses nan, which the figures use to pad shorter curves).
std::vector<std::pair<double, double>> column_figure_curve(const fs::path& csv, std::size_t k) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // the header
  std::vector<std::pair<double, double>> out;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    if (!std::isnan(row.at(2 * k))) out.push_back({row[2 * k], row[2 * k + 1]});
  }
  return out;
}

}  // namespace

TEST_CASE("report: a column's section sets its profiles beside the DEM runs it names",
          "[comparison][column]") {
  fs::remove_all(kColumnWork);
  const fs::path run = kColumnWork / "column";
  const nlohmann::json dem = {fs::relative(kColumnDemRun, fs::absolute(run)).generic_string()};
  const auto r = column::run_column_into(short_column(), run, false, {}, dem);
  REQUIRE(r.status == "complete");
  const fs::path html = kColumnWork / "report" / "report.html";
  const auto figures = comparison::write_report({run}, html);
  CHECK(figures.size() == 7);
  const fs::path dir = kColumnWork / "report" / "report_files" / "column-0-column";
  // the DEM's curve (drawn first): its last window's bins up to the column's 14 d50
  const auto dem_curve = column_figure_curve(dir / "column_velocity.csv", 0);
  const auto p = io::read_csv_table(kColumnDemRun / "profiles.csv");
  const auto w = p.values("u_x_mm_window"), z = p.values("z_over_d50");
  std::size_t expected = 0;
  for (std::size_t k = 0; k < w.size(); ++k) expected += (w[k] == w.back() && z[k] <= 14.0);
  CHECK(dem_curve.size() == expected);
  // the column's curve: its profile's 28 element centres at the end, v_x from 1 at the wall down
  const auto col = column_figure_curve(dir / "column_velocity.csv", 1);
  REQUIRE(col.size() == 28);
  CHECK(col.front().second == Approx(r.profiles.back().z_over_d50.front()).epsilon(1e-6));
  CHECK(col.front().second == Approx(0.25).margin(0.01));  // 0.25 d50 before it dilated
  CHECK(col.front().first > col.back().first);
  CHECK(fs::exists(dir / "column_void_ratio.svg"));
  // the grains turn with the wall's shear in both, whatever each engine calls the sense: the
  // DEM's spin over its band (lowest 6 d50) and the column's are positive in the column's sense
  double dem_spin = 0.0, col_spin = 0.0;
  for (const auto& [x, zz] : column_figure_curve(dir / "column_spin.csv", 0))
    if (zz < 6.0) dem_spin += x;
  for (const auto& [x, zz] : column_figure_curve(dir / "column_spin.csv", 1))
    if (zz < 6.0) col_spin += x;
  CHECK(dem_spin > 0.0);
  CHECK(col_spin > 0.0);

  // a DEM run the manifest names but that is gone: refused before anything is written
  const fs::path run2 = kColumnWork / "column2";
  column::run_column_into(short_column(), run2, false, {}, nlohmann::json{"../no_such_run"});
  const fs::path html2 = kColumnWork / "report2" / "report.html";
  CHECK_THROWS_AS(comparison::write_report({run2}, html2), InputError);
  CHECK_FALSE(fs::exists(html2.parent_path()));
}
