#pragma once
// How far a replay is from the DEM (issue 6 "Metrics"), over the DEM rows the replay reached.
#include <nlohmann/json.hpp>
#include <optional>

#include "comparison/replay/dem_run.hpp"
#include "comparison/replay/replay.hpp"
#include "statistics/steady_state.hpp"

namespace iwb::comparison {

// The residual window, the DEM summary's own (statistics/steady_state.hpp), so that the DEM's
// numbers here equal its summary.json.
using statistics::kResidualWindowShare;

struct Metrics {
  double rmse_tau_kPa;
  double peak_friction_dem, peak_friction_model;
  double residual_friction_dem, residual_friction_model;  // mean over the last fifth of u_x
  double u_x_at_peak_dem_mm, u_x_at_peak_model_mm;
  std::optional<double> rmse_u_n_mm;       // CNL and CNS: dilation u_n(u_x)
  std::optional<double> rmse_sigma_n_kPa;  // CNS and CV: the normal-stress path
  std::size_t rows_compared;
  // The last fifth of a cyclic run is the end of its path, not a residual (issue 59): named
  // end_of_path_friction in the record, as in its summary.json.
  bool cyclic = false;
};

// The record's key of the friction over the last fifth: "residual_friction" or, for a cyclic run,
// "end_of_path_friction".
const char* end_friction_key(bool cyclic);

Metrics compare(const DemRun& dem, const Replay& replay);
nlohmann::json to_json(const Metrics& m);

}  // namespace iwb::comparison
