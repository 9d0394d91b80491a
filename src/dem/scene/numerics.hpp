#pragma once
// Numbers an engine needs that follow from a scene: timestep, geometry in z, step counts. Both
// engines use the same ones, so that a difference between them is the contact law, not the setup.
#include "dem/scene/scene.hpp"

namespace iwb::dem {

struct Numerics {
  double dt, skin, d50;
  double wall_top, ins_zlo, ins_zhi, plate_z, zlo, zhi;
  double band_zlo, band_zhi;
  long shear_steps, ts_every, progress_every, profile_every, profile_repeat, vtk_every, relax_steps;
  long settle_steps;
  // Windows the servo may spend bringing the plate onto the grains (sigma below
  // kApproachSigmaShare of the target), counted apart from the max_windows of acceptance: the
  // approach takes a time (the gap over the plate's top speed), and in steps it grows as the
  // timestep shrinks with stiffer grains (issue 20: E = 1e9 used 55 of 60 windows approaching).
  long approach_windows;
};

// The plate has reached the grains once sigma exceeds this share of the target.
inline constexpr double kApproachSigmaShare = 0.5;

double rayleigh_time(const Particles& p);
Numerics derive(const Scene& s);

}  // namespace iwb::dem
