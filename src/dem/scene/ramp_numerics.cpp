#include "dem/scene/ramp_numerics.hpp"

#include <fmt/core.h>

#include <cmath>

namespace iwb::dem {

nlohmann::json ramp_numerics(const Scene& s, double dt) {
  const Shear& sh = s.shear;
  const std::string rule =
      sh.ramp_s > 0.0
          ? fmt::format("wall speed linear from 0 to v over {:g} x 2 H / c_s (H = {:g} mm)",
                        sh.ramp_transits, s.height_m * 1e3)
          : std::string(sh.cyclic() ? "none: cycles start at full speed" : "none: instant start");
  return {{"rule", rule},
          {"ramp_transits", sh.ramp_transits},
          {"shear_wave_speed_estimate_m_s", sh.shear_wave_speed_m_s},
          {"time_s", sh.ramp_s},
          {"steps", std::lround(sh.ramp_s / dt)},
          {"displacement_mm", sh.ramp_displacement_m() * 1e3}};
}

}  // namespace iwb::dem
