#pragma once
// The run-directory contract's wall zone (../shared/spec/DEM.md, timeseries.csv `e_band`): the
// void ratio of the grains whose centres lie in the lowest 10 d50 above the wall's mean height,
// or the lowest half of the specimen if that is lower. Both engines write it by this rule and
// the comparison reads a dilation of the wall zone from it, so the rule is written once.
#include <algorithm>

namespace iwb {

// Thickness of the wall zone, in the unit of its arguments.
inline double wall_zone_thickness(double d50, double specimen_height) {
  return std::min(10.0 * d50, 0.5 * specimen_height);
}

}  // namespace iwb
