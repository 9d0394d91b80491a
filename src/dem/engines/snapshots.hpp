#pragma once
// The engines' dumps of the shear stage as the run directory's VTK XML series (DEM.md, issue 21):
// vtk/particles_<step>.vtp (grains: id, radius, mass, velocity, angular velocity and displacement
// since the start of shear), vtk/contacts_<step>.vtp (each contact a branch segment with the force
// on its first end), vtk/walls_<step>.vtp, each series with its .pvd by shear time.
//
// Both engines dump into <engine>/dumps/ in one raw layout, so that only the file names and the
// frame differ here: particles as legacy VTK with point arrays id, radius, mass, v, omega and
// optionally i (LIGGGHTS's image flags: positions wrapped) and type (2 = a glued wall sphere);
// contact lists as text with 15 columns per row (LIGGGHTS's dump local of pair/gran/local and
// wall/gran/local with id pos force contactPoint):
//   pairs_<step>.txt:          x1 y1 z1 x2 y2 z2 id1 id2 periodic fx fy fz cx cy cz (f on 1)
//   wall_contacts_<step>.txt:  cx cy cz x y z mesh triangle id fx fy fz - - -     (f on the grain)
// Conversion is idempotent: a snapshot whose .vtp files exist is not read again, and the raw
// dumps are removed once the series is complete.
#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "dem/scene/scene.hpp"

namespace iwb::dem {

struct DumpNames {
  std::string particles, walls;  // regexes with one capture group, the engine step
};

struct SnapshotFrame {
  Eigen::Vector3d shift =
      Eigen::Vector3d::Zero();  // engine frame + shift = scene frame (z from the wall's base)
  long step0 = 0;               // the start of shear
  double dt = 0.0;
};

// Returns the number of snapshots in the series.
int write_snapshot_series(const Scene& scene, const std::filesystem::path& dumps,
                          const DumpNames& names, const SnapshotFrame& frame,
                          const std::filesystem::path& vtk_dir);

}  // namespace iwb::dem
