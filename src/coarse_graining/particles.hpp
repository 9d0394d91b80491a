#pragma once
// What the coarse-graining needs of a DEM snapshot, engine-neutral: grains and contacts in the
// scene's frame (x along shear, z up from the wall's base), SI units. The run directory's .vtp
// files hold exactly this (dem/engines/snapshots.hpp writes them from either engine).
#include <Eigen/Core>
#include <vector>

namespace iwb::coarse_graining {

struct Grain {
  Eigen::Vector3d position =
      Eigen::Vector3d::Zero();  // wrapped or not: the grids wrap x themselves
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d spin = Eigen::Vector3d::Zero();  // angular velocity, rad/s
  double radius = 0.0, mass = 0.0;
};

// One contact, counted once. `force` acts on the grain at `from`. For a contact between two grains
// `to` is the partner's centre (its periodic image next to `from`); for a contact with the wall,
// the plate or a glued wall sphere, `to` is the contact point, so that the branch ends on the
// boundary (Weinhart et al. 2012, sec. 3: the boundary's force enters where it acts).
struct Contact {
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero(),
                  force = Eigen::Vector3d::Zero();
  bool boundary = false;
};

// The cell is periodic in x and y with these lengths; z is bounded by the wall and the plate.
struct PeriodicCell {
  double length_x = 0.0, length_y = 0.0;
};

struct Snapshot {
  std::vector<Grain> grains;
  std::vector<Contact> contacts;
};

}  // namespace iwb::coarse_graining
