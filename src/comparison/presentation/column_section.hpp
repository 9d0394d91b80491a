#pragma once
// The report's section of a micro-polar column run (`iwb column`, src/column/README.md): its
// profiles over the height at the end of the travel beside the DEM runs it was run for (their
// last window of profiles.csv), and tau/sigma_n and u_n along the travel beside theirs. Read from
// the run directories' files alone: the report knows neither the column's code nor an engine's.
#include <filesystem>
#include <string>
#include <vector>

namespace iwb::comparison {

// A directory written by `iwb column` (its manifest's kind).
bool is_column_run(const std::filesystem::path& dir);

// InputError where a column run's manifest names a DEM run (relative to the column's directory)
// without profiles.csv and timeseries.csv: checked before the report writes anything.
void require_column_run(const std::filesystem::path& run);

struct ColumnSection {
  std::string html;
  std::vector<std::filesystem::path> figures;  // SVG files written under fig_dir
};

// `fig_dir` receives the figures; `data_prefix` is how the page names the folder of their data.
ColumnSection column_section(const std::filesystem::path& run, const std::filesystem::path& fig_dir,
                             const std::string& data_prefix);

}  // namespace iwb::comparison
