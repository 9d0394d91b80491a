#pragma once
// The band as the coarse-grained fields of the DEM run show it (issue 21), for the report: heat
// maps of the shear rate |dV_x/dz| over x-z at up to three wall displacements, and the profiles of
// the second half of the travel (solid fraction, velocity, stresses) with the continuum model's
// shear-zone thickness d_s marked, and the void ratio's change inside each d_s: the DEM's from the
// coarse-grained solid fraction over 0 <= z <= d_s, the model's (1 + e0) u_n / d_s. Read from the
// run directory's fields/ (DEM.md), nothing else.
#include <filesystem>
#include <string>
#include <vector>

#include "comparison/presentation/figure.hpp"

namespace iwb::comparison {

struct ShearZoneMark {
  std::string label;  // "d_s predicted", "d_s fitted"
  double d_s_d50;
  std::vector<double> u_x_mm, u_n_mm;  // the model's dilation along the DEM's path (compare.csv)
  double e0;                           // the model's initial void ratio
};

// Empty if the run has no fields (coarse-graining off, or a run from before issue 21).
std::vector<Figure> band_figures(const std::filesystem::path& dem_dir,
                                 const std::vector<ShearZoneMark>& marks);

}  // namespace iwb::comparison
