#pragma once
// A column's run directory (CONVENTIONS.md "Results"): manifest.json (the spec, how the run ended,
// the band at each profile), timeseries.csv (the wall's tau, sigma_n, u_n and slip along the
// travel), profiles.csv (the fields over the height at each window's end, as the DEM's
// profiles.csv), band.csv (the band's widths along the travel) and summary.json (its quantities
// under a DEM run's summary names: peak_friction, dilation_mm; for `iwb claims`).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "column/column.hpp"

namespace iwb::column {

nlohmann::json spec_json(const ColumnSpec& spec);

// Claims `dir` for a column run (refusing a foreign or earlier one unless `force`), runs the
// column and writes its files; the manifest says "running" while it runs and names `dem_runs`
// (paths relative to `dir`), the DEM runs the column is set beside.
ColumnResult run_column_into(const ColumnSpec& spec, const std::filesystem::path& dir, bool force,
                             const nlohmann::json& inputs, const nlohmann::json& dem_runs,
                             const std::function<void(long, long)>& progress = {});

}  // namespace iwb::column
