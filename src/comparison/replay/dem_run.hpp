#pragma once
// A DEM run directory as the comparison layer sees it: the contract of DEM.md, validated.
// Nothing here knows which engine wrote it.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cycles/cycle_quantities.hpp"
#include "driver/control.hpp"

namespace iwb::comparison {

struct DemRun {
  std::filesystem::path dir;
  std::string status;
  std::string engine;
  driver::BoundaryKind boundary;
  double sigma_n0_kPa;  // the scene's consolidation stress
  double K_kPa_per_mm;  // CNS
  double d50_mm;
  double R_n;
  double wall_zone_mm = 0.0;  // the zone whose void ratio is e_band (common/band_zone.hpp)
  // the wall's mean |dz/dx| (summary.json); empty for a summary written before it was recorded
  std::optional<double> wall_mean_abs_slope;
  // the time series, contract units
  std::vector<double> t_s, u_x_mm, u_n_mm, sigma_n_kPa, tau_kPa, e_band;
  nlohmann::json summary;  // may be empty (partial runs)
  // manifest /scene/resolved without its seed (runs of one scene with other seeds have equal
  // ones) and /scene/text (its [requirements] state the tolerances a model is judged by)
  nlohmann::json scene_but_seed;
  // cycles in its shear stage: its end state is an end of path, not a residual (issue 59)
  bool cyclic() const {
    return scene_but_seed.is_object() && scene_but_seed.value("/shear/cycles"_json_pointer, 0) > 0;
  }
  std::string scene_text;

  std::optional<double> band_d50() const;  // the measured wall band, if the run localised there
};

// Reads and validates `dir`. Missing files, a missing or misnamed column, non-monotonic time, a
// non-number or a truncated row are InputErrors naming the file and line; a run whose status is
// not "complete" is refused unless `allow_partial`.
DemRun load_dem_run(const std::filesystem::path& dir, bool allow_partial = false);

// What the run's path is, below every verdict that reads it (the seed statistics and the cyclic
// verdicts alike): the wall's program of a cyclic run (its manifest's /scene/resolved/shear),
// nullopt when the run is monotonic ...
std::optional<cycles::Program> cyclic_program(const DemRun& dem);
// ... and a cyclic run's travel at each row: its wall moves at v throughout (no ramp with cycles),
// so v t.
std::vector<double> cyclic_travel(const DemRun& dem);

// The columns of timeseries.csv the comparison needs (names carry the units).
const std::vector<std::string>& required_timeseries_columns();

}  // namespace iwb::comparison
