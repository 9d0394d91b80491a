#include "dem/scene/numerics.hpp"

#include <algorithm>
#include <cmath>

#include "common/band_zone.hpp"

namespace iwb::dem {

namespace {

constexpr double kSkinD50 = 0.3;
constexpr double kLooseSolidFraction = 0.30;  // insert/pack fills a region reliably this loosely
constexpr int kProfileEvery = 10;             // ave/spatial samples every 10 steps

}  // namespace

double rayleigh_time(const Particles& p) {
  const double G = p.youngs_modulus_Pa / (2.0 * (1.0 + p.poisson));
  return M_PI * 0.5 * p.d_min() * std::sqrt(p.density_kg_m3 / G) / (0.1631 * p.poisson + 0.8766);
}

Numerics derive(const Scene& s) {
  Numerics n{};
  n.d50 = s.particles.d50_m;
  n.dt = s.dt_fraction * rayleigh_time(s.particles);  // [numerics] dt_fraction, default 0.15
  n.skin = kSkinD50 * n.d50;
  const double dmax = s.particles.d_max();
  n.wall_top = s.wall.height_m;
  n.ins_zlo = n.wall_top + 0.1 * dmax;
  // The insertion region holds the requested grains at a loose packing; the servo compacts them.
  n.ins_zhi = n.ins_zlo + s.particle_count * s.particles.mean_particle_volume_m3() /
                              (s.area_m2() * kLooseSolidFraction);
  n.plate_z = n.ins_zhi + s.plate.height_m + 0.1 * dmax;
  n.zlo = -dmax;
  n.zhi = n.plate_z + 2.0 * dmax;
  n.band_zlo = s.wall.mean_height_m();
  n.band_zhi = n.band_zlo + wall_zone_thickness(n.d50, s.height_m);  // the time series' band
  const double step_u = s.shear.velocity_m_s * n.dt;                 // wall displacement per step
  // the ramp (if any) adds half its time: the wall covers v T / 2 while ramping for T
  n.shear_steps = long(std::ceil(s.shear.duration_s() / n.dt));
  n.ts_every = std::max(1L, long(std::lround(s.outputs.timeseries_every_m / step_u)));
  n.progress_every = std::max(1L, n.shear_steps / 50);
  n.profile_every = std::max(long(kProfileEvery), (n.shear_steps / s.outputs.profile_windows) /
                                                      kProfileEvery * kProfileEvery);
  n.profile_repeat = std::max(1L, std::min(100L, n.profile_every / kProfileEvery / 2));
  n.vtk_every = std::max(1L, long(std::lround(s.outputs.vtk_every_m / step_u)));
  n.relax_steps = 2L * s.consolidation.window_steps;
  n.settle_steps = s.consolidation.window_steps;
  // the whole initial gap at the servo's top speed, twice over, plus slack for the slow-down
  const double approach_s = (n.plate_z - n.wall_top) / s.servo.vel_max_m_s;
  n.approach_windows =
      10 + long(std::ceil(2.0 * approach_s / (double(s.consolidation.window_steps) * n.dt)));
  return n;
}

}  // namespace iwb::dem
