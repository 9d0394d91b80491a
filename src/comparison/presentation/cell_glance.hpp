#pragma once
// The report's first table (issue 59 item 5): one row per cell, not per run. A cell is the runs one
// model was judged on with the same seed statistics: each run's comparison names the runs whose
// mean and scatter it was judged against (compare.json "seeds"/"runs"), and the runs of one
// scene's seeds name the same set. Per quantity the row gives the cell's verdict from those
// statistics (every run of the cell is judged against the same seed mean, so its runs agree but
// where their replays differ), with the cause of a break where the form limit named one and the
// seeds a verdict within the DEM's scatter would need.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iwb::comparison {

struct CellRow {
  std::string label;               // the runs' names with the seed replaced by '*'
  std::string model, boundary;     // the model judged; CNL, CNS, CV
  double R_n = 0.0, d50_mm = 0.0;  // the wall and the grains, from the first run
  double sigma_n0_kPa = 0.0;       // mean over the cell's runs
  int seeds = 0;                   // runs in the seed statistics (compare.json seeds.runs)
  std::vector<std::size_t> runs;   // indices into the comparisons given
  // per quantity key of quantity_table(): the cell's predicted verdict, e.g. "breaks (form)",
  // "within DEM scatter (7 seeds)", "breaks 2 · within DEM scatter 1" where runs differ; absent
  // where the quantity was not judged
  std::vector<std::pair<std::string, std::string>> verdicts;
};

// The comparisons (compare.json), grouped into cells in the order their first run appears.
std::vector<CellRow> cell_rows(const std::vector<nlohmann::json>& comparisons);

// The HTML table of the rows, each run linked to its section (#run-<index>).
std::string cell_glance_html(const std::vector<CellRow>& rows);

}  // namespace iwb::comparison
