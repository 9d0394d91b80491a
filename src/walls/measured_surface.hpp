#pragma once
// A measured wall surface from a file (issue 36): a line profile (CSV `x_mm,z_mm`, extruded along
// y) or a height map (CSV of heights in mm, one row per line along x, rows stepping in y, on a
// square grid of `spacing`). A measurement is not periodic, so a window of the box's size is cut
// from it (from `offset` along x) and made to tile the box: the straight line (for a map, the
// bilinear plane) through the window's edge heights is subtracted, so that the far edge meets the
// near one in height (a slope may still change across the seam). The window's own R_n is kept
// beside the tiled one, so what tiling did to R_n is on record. The lowest point is laid on the
// base plane. A measurement finer than `resample_m` is averaged down to it.
#include <string>
#include <vector>

#include "walls/height_map.hpp"

namespace iwb::walls {

enum class MeasuredLayout { kLine, kMap };

struct MeasuredSurfaceSpec {
  std::string path;
  MeasuredLayout layout = MeasuredLayout::kLine;
  double spacing_m = 0.0;  // map: the grid's spacing in x and y
  double offset_m = 0.0;   // where along x the window starts
  double scale = 1.0;      // heights multiplied by this (0.5: half as rough)
  // Samples closer than this are averaged over cells of about this size (x and, for a map, y): a
  // grain feels no finer feature, and a profilometer's noise, which dominates slopes at the
  // instrument's spacing, goes. 0: as measured.
  double resample_m = 0.0;
};

struct MeasuredSurface {
  HeightMap map;
  double window_r_max_m;  // the largest R_max over d50 windows that do not cross the seam
  std::vector<std::string> warnings;
};

// InputError naming the file and the row for a file that cannot be used: missing, a non-number,
// NaN or inf, x not increasing, rows of unequal length, a measurement smaller than the box, or
// coarser than d50/4 (R_max over d50 needs at least four samples).
MeasuredSurface measured_surface(const MeasuredSurfaceSpec& spec, double length, double width,
                                 double d50);

}  // namespace iwb::walls
