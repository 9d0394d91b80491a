#include "dem/scene/shear_start.hpp"

#include <cmath>

namespace iwb::dem {

double effective_medium_shear_wave_speed(double youngs_modulus_Pa, double poisson,
                                         double density_kg_m3, double pressure_Pa,
                                         double solid_fraction, double coordination) {
  const double nu = poisson;
  const double G = youngs_modulus_Pa / (2.0 * (1.0 + nu));
  const double bracket = 3.0 * coordination * coordination * solid_fraction * solid_fraction * G *
                         G * pressure_Pa / (2.0 * M_PI * M_PI * (1.0 - nu) * (1.0 - nu));
  const double G_eff = (5.0 - 4.0 * nu) / (5.0 * (2.0 - nu)) * std::cbrt(bracket);
  return std::sqrt(G_eff / (solid_fraction * density_kg_m3));
}

double ramp_time_s(double transits, double height_m, double shear_wave_speed_m_s) {
  return transits * 2.0 * height_m / shear_wave_speed_m_s;
}

}  // namespace iwb::dem
