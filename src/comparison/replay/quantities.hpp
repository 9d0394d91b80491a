#pragma once
// The quantities of interest by which a continuum model is judged against the DEM (issue 14):
// shear stress (peak, its displacement, residual) and dilation (total and its rate) under CNL and
// CNS, the normal-stress change (at the end, and the lowest on the way) under CNS and CV. Each is
// computed the same way from a DEM curve and from a model's replay of it, so that their difference
// is the model's error alone.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "driver/control.hpp"
#include "statistics/steady_state.hpp"

namespace iwb::comparison {

struct QuantityInfo {
  const char* key;   // as in a scene's [requirements] and in compare.json
  const char* name;  // for people
  const char* unit;  // of the value; "" for ratios
  double tolerance;  // default relative tolerance (issue 14), overridden by [requirements]
  // Relative errors are taken against max(|DEM value|, floor): a DEM value near zero (a flat
  // wall that barely dilates) would otherwise turn a small absolute miss into an infinite one.
  double floor;
  bool floor_in_d50;  // the floor is in grain diameters (lengths), else in the value's unit
};

// In the order reports list them.
const std::vector<QuantityInfo>& quantity_table();
const QuantityInfo& quantity(const std::string& key);
// "peak_friction 10 %, u_x_at_peak 30 %, ...": tolerances as `iwb compare --help` lists them.
std::string tolerances_text(const std::vector<std::pair<std::string, double>>& keyed);
// Each quantity's default tolerance, from the table above (the one place it is written).
std::string default_tolerances_text();

// The quantities that a boundary condition leaves free to judge: CV fixes u_n, CNL fixes sigma_n.
// A cyclic run is judged on its end-of-path friction instead of a residual, and on no critical
// state: its path reverses, so neither is reached (issue 59, the cyclic end state named apart).
std::vector<std::string> judged_quantities(driver::BoundaryKind boundary, bool cyclic = false);

// A response along u_x in contract units (compression positive, u_n > 0 dilation); `rows` of
// each series are used (a replay that stopped early has fewer than the DEM). With the void ratio
// of the wall zone (the contract's e_band, common/band_zone.hpp) and that zone's thickness, the
// dilation of the wall zone alone: what the wall's band did, whatever else moved the plate.
struct Curve {
  const std::vector<double>& u_x_mm;
  const std::vector<double>& tau_kPa;
  const std::vector<double>& sigma_n_kPa;
  const std::vector<double>& u_n_mm;
  const std::vector<double>* e_band = nullptr;
  double wall_zone_mm = 0.0;
};

// Each quantity of `keys` from the curve; nullopt where the curve cannot give it (fewer than two
// rows, or no rows in the last fifth; a critical-state value whose decay the curve does not
// resolve, statistics/steady_state.hpp).

std::map<std::string, std::optional<double>> evaluate_quantities(
    const Curve& curve, const std::vector<std::string>& keys);

// Whether the friction has settled over the last fifth (statistics/steady_state.hpp, the decay
// fitted from the peak on, blocks of kSteadyBlockD50 grains): what the residual verdict requires
// of every DEM run it rests on.
std::optional<statistics::SteadyState> friction_steady_state(const Curve& curve, double d50_mm);

// The quantities read from a decay fitted beyond the run's end: "extrapolated" wherever shown.
bool is_extrapolated(const std::string& key);

}  // namespace iwb::comparison
