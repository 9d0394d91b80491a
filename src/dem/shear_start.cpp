#include "dem/shear_start.hpp"

#include <fmt/core.h>

#include <cmath>

namespace iwb::dem {

double effective_medium_shear_wave_speed(const Particles& p, double pressure_Pa,
                                         double solid_fraction, double coordination) {
  const double nu = p.poisson;
  const double G = p.youngs_modulus_Pa / (2.0 * (1.0 + nu));
  const double bracket = 3.0 * coordination * coordination * solid_fraction * solid_fraction * G *
                         G * pressure_Pa / (2.0 * M_PI * M_PI * (1.0 - nu) * (1.0 - nu));
  const double G_eff = (5.0 - 4.0 * nu) / (5.0 * (2.0 - nu)) * std::cbrt(bracket);
  return std::sqrt(G_eff / (solid_fraction * p.density_kg_m3));
}

double ramp_time_s(double transits, double height_m, double shear_wave_speed_m_s) {
  return transits * 2.0 * height_m / shear_wave_speed_m_s;
}

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
