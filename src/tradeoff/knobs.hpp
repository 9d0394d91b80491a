#pragma once
// The resolution knobs of a DEM scene (issue 7, item 4) and the scenes derived by turning them:
// box size in d50 (length and height, hence the particle count), stiffness level kappa (through
// Young's modulus), timestep fraction of the Rayleigh time, and shear speed (through the inertial
// number). Each variant is the base scene with a few dotted keys set (io/toml_override.hpp), so it
// runs as one job of a campaign (src/campaign/).
#include <string>
#include <vector>

#include "campaign/jobs.hpp"
#include "dem/scene/scene.hpp"

namespace iwb::tradeoff {

// One knob: its name on the command line and in job names, and the factor on its value that
// resolves the DEM better (2: larger box, stiffer grains; 0.5: smaller step, slower shear).
struct Knob {
  std::string name;  // box, kappa, dt, I
  std::string meaning;
  double refining_factor;
};

const std::vector<Knob>& all_knobs();
const Knob& find_knob(const std::string& name);  // InputError listing the knobs
std::vector<std::string> parse_knob_list(const std::string& comma_separated);

// The keys to set on `base` (as read from `base_text`) to scale each named knob's value by its
// factor. box: length and height x f and the particle count with the volume; where the scaled
// length is refused by the scene rules (a box at least 10 d_max long, a whole number of wall
// pitches) the length stays and only the height scales. kappa: E x f^1.5 (kappa ~ E^(2/3)).
// dt: numerics.dt_fraction x f. I: shear.inertial_number (or velocity_mm_s) x f. Where the
// timestep changes (dt, kappa), consolidation.window_steps scales with 1/dt so that a window lasts
// as long as the base's; in a taller box consolidation.max_windows scales with the height.
std::vector<campaign::Setting> knob_settings(
    const dem::Scene& base, const std::string& base_text,
    const std::vector<std::pair<std::string, double>>& knob_factors);

// The base scene text with `settings` applied and a header naming them; validated (InputError
// naming the variant and the scene's complaint).
std::string derived_scene(const std::string& base_text, const std::string& base_name,
                          const std::vector<campaign::Setting>& settings,
                          const std::string& variant);

}  // namespace iwb::tradeoff
