#pragma once
// Derived quantities of a DEM run (DEM.md "What the comparison layer derives"), computed from the
// contract tables only, so they mean the same for every engine.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cycles/cycle_quantities.hpp"
#include "dem/scene/scene.hpp"
#include "io/csv_table.hpp"
#include "statistics/local_rate.hpp"
#include "statistics/steady_state.hpp"

namespace iwb::dem {

struct Summary {
  double peak_friction = 0.0;  // max tau/sigma_n (sigma_n on the tested wall)
  double u_x_at_peak_mm = 0.0;
  // mean |tau|/sigma_n over the last fifth of the travel: the residual of a monotonic run, the
  // end-of-path friction of a cyclic one (issue 59: not a residual, and named apart)
  double end_friction = 0.0;
  // the residual rule of statistics::residual_steady_state (the comparison's own); only then is
  // the end friction a "residual". nullopt: too few rows to tell.
  std::optional<statistics::SteadyState> residual_test;
  bool steady() const { return residual_test && residual_test->steady; }
  // d u_n / d u_x over kRateHalfSpanD50 either side of the peak friction, in blocks of
  // kRateBlockD50 (statistics/local_rate.hpp): the dilatancy rate at the peak with
  // its 95 % interval; nullopt where the run is too short for three blocks
  std::optional<statistics::LocalRate> rate_at_peak;
  double dilation_mm = 0.0;            // u_n at the end
  double dilatancy_angle_deg = 0.0;    // atan(du_n/du_x) over the last fifth
  double sigma_n_mean_kPa = 0.0;       // during shear, on the wall
  double sigma_n_max_deviation = 0.0;  // max |sigma_n / target - 1| during shear (CNL)
  // "localised at the wall", "split between wall and plate", "localised at the plate",
  // "distributed shear" or "no profile"
  std::string shear_mode;
  double far_field_speed = 0.0;              // median vx/v(first layer) over the middle third
  double wall_share = 0.0;                   // share of the velocity drop taken next to the wall
  std::optional<double> wall_band_d50;       // from the wall to within 10 % of the far field
  std::optional<double> plate_band_d50;      // from the plate down to within 10 % of it
  std::optional<double> band_thickness_d50;  // 0.9 -> 0.1 of the first layer's speed, only
                                             // when the far field is at rest (DEM.md)
  std::optional<double> band_thickness_erf_d50;  // erfc fit of the wall band
  double wall_slip = 0.0;                        // 1 - v(first layer)/v(wall)
  std::optional<double> e_band;                  // void ratio in the band (or the lowest 10 d50)
  // the tested wall's mean |dz/dx| along the shear (walls/descriptors.hpp): what a model whose
  // asperities ride reads of the wall beside R_n (issue 56)
  double wall_mean_abs_slope = 0.0;

  std::optional<cycles::CyclicQuantities> cyclic;  // cyclic shear only: per cycle, and after them
};

// The span of the dilatancy rate at the peak: half a grain either side, in blocks of an eighth of a
// grain (8 blocks: a t-interval with 7 degrees of freedom). On the truth runs (d50 2 mm) the rate
// stays within 10 % of its largest over 1-3 mm of travel (R_n 0.5; 1-2 mm at R_n 0.25): a span of
// one grain lies within that zone, where a span of four grains took in the start's contraction
// and the fall after the peak and read 0.18-0.20 for 0.27-0.30.
inline constexpr double kRateHalfSpanD50 = 0.5;
inline constexpr double kRateBlockD50 = 0.125;

Summary summarize(const Scene& scene, const io::CsvTable& timeseries, const io::CsvTable& profiles);
nlohmann::json to_json(const Summary& s);

}  // namespace iwb::dem
