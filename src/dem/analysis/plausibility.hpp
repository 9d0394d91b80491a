#pragma once
// Whether a DEM interface-shear run did what its scene asked (issue 15): the wall travelled the
// asked distance (not short of it, not grossly past it), the time series has the rows the scene's
// output cadence promises, every value is finite, the grains stayed in contact with the wall,
// and the boundary condition held. Pure functions of the scene and the contract's time series,
// so they mean the same for LIGGGHTS and YADE; `iwb dem run` records every check in the manifest
// and marks the run failed when one fails, `iwb dem summary` refuses such files.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dem/scene/scene.hpp"
#include "io/csv_table.hpp"

namespace iwb::dem {

// What the scene asked of the shear stage, in contract units (mm, kPa).
struct Asked {
  double travel_mm = 0.0;     // the wall's whole path (cyclic: 4 A per cycle)
  double row_every_mm = 0.0;  // the time series' cadence in wall displacement
  int reversals = 0;          // cyclic: two per cycle, where the rows cut the turning point short
  driver::BoundaryKind boundary = driver::BoundaryKind::kCNL;
  double sigma_n0_kPa = 0.0;  // CNL target; CNS and CV: the stress at the start of shear
  double K_kPa_per_mm = 0.0;  // CNS: d sigma_n = K d u_n
  double d50_mm = 0.0;
};
Asked asked_by(const Scene& scene);

// One check: `value` compared with `limit` by `comparison` ("<=", ">=" or ">"). A NaN value
// (nothing to measure: no rows) fails.
struct PlausibilityCheck {
  std::string name;
  double value = 0.0;
  std::string comparison;
  double limit = 0.0;
  bool passed = false;
  std::string measures;  // what `value` is, with its unit
  // Beyond this the check passes but the manifest carries a warning (the boundary condition held
  // only loosely); NaN when the check has no such level.
  double warning_limit = NAN;
};

// Tolerances (why each value: src/dem/README.md, "Plausibility"):
inline constexpr double kMinRowShare = 0.9;  // rows against travel / cadence
inline constexpr int kMinRows = 2;           // and never fewer: a start and an end
inline constexpr double kTravelRows = 2.0;   // the last row may precede the end by a row,
                                             // and each reversal's rows miss up to one more
// |mean sigma_n / target - 1| over the shear stage. With the servo's gain from its loop number
// (dem/scene/scene.hpp) the convergence runs hold 1-7 % (the grains' weight adds ~1.2 % at 20 d50;
// the rest is the servo trailing the dilation, ~ plate speed / (vel_max kp): 5.6 % at I 1e-3 and E
// 4.2e9, 1.2 % at I 3e-4); with the earlier fixed gain the stiffest were 8-60 % off.
inline constexpr double kNormalStressHeld = 0.2;
inline constexpr double kNormalStressWarning = 0.05;
inline constexpr double kNormalDisplacementHeldD50 = 0.01;  // CV: max |u_n| in d50

std::vector<PlausibilityCheck> plausibility_checks(const Asked& asked,
                                                   const io::CsvTable& timeseries);

// "name = value, must be <= limit (what it measures)" of every failed check, joined by "; ";
// nothing when all passed.
std::optional<std::string> failure_reason(const std::vector<PlausibilityCheck>& checks);
// One line per passed check beyond its warning level.
std::vector<std::string> plausibility_warnings(const std::vector<PlausibilityCheck>& checks);
nlohmann::json to_json(const std::vector<PlausibilityCheck>& checks);

}  // namespace iwb::dem
