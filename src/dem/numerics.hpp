#pragma once
// Numbers an engine needs that follow from a scene: timestep, geometry in z, step counts. Both
// engines use the same ones, so that a difference between them is the contact law, not the setup.
#include "dem/scene.hpp"

namespace iwb::dem {

struct Numerics {
  double dt, skin, d50;
  double wall_top, ins_zlo, ins_zhi, plate_z, zlo, zhi;
  double band_zlo, band_zhi;
  long shear_steps, ts_every, progress_every, profile_every, profile_repeat, vtk_every, relax_steps;
  long settle_steps;
};

double rayleigh_time(const Particles& p);
Numerics derive(const Scene& s);

}  // namespace iwb::dem
