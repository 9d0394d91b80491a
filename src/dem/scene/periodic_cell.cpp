#include "dem/scene/periodic_cell.hpp"

namespace iwb::dem {

namespace {

// insert/pack fills a region reliably this loosely (as dem/scene/numerics.cpp's insertion region)
constexpr double kInsertSolidFraction = 0.30;

}  // namespace

PeriodicServoGains periodic_servo_gains(const Scene& s, double dt) {
  return {s.servo.vel_max_m_s / s.boundary.sigma_n_Pa,
          0.6 * s.height_m / (s.particles.youngs_modulus_Pa * dt)};
}

double periodic_insertion_height(const Scene& s, double margin) {
  const double lx = s.length_m - 2.0 * margin, ly = s.width_m - 2.0 * margin;
  return s.particle_count * s.particles.mean_particle_volume_m3() /
             (lx * ly * kInsertSolidFraction) +
         2.0 * margin;
}

void band_is_the_cell(io::CsvTable& timeseries) {
  const int e = timeseries.column("e_specimen"), band = timeseries.column("e_band");
  for (auto& r : timeseries.rows) r[band] = r[e];
}

}  // namespace iwb::dem
