#pragma once
// The band as the coarse-grained fields of the DEM run show it (issue 21), for the report: heat
// maps of the shear rate |dV_x/dz| over x-z at up to three wall displacements, and the profiles of
// the second half of the travel (solid fraction, velocity, stresses) with the continuum model's
// shear-zone thickness d_s marked. Read from the run directory's fields/ (DEM.md), nothing else.
#include <filesystem>
#include <string>
#include <vector>

#include "comparison/figure.hpp"

namespace iwb::comparison {

struct ShearZoneMark {
  std::string label;  // "d_s predicted", "d_s fitted"
  double d_s_d50;
};

// Empty if the run has no fields (coarse-graining off, or a run from before issue 21).
std::vector<Figure> band_figures(const std::filesystem::path& dem_dir, const std::vector<ShearZoneMark>& marks);

}  // namespace iwb::comparison
