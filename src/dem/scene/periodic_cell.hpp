#pragma once
// What the periodic soil cell (`iwb dem soiltest --cell periodic`, issue 38) is in either engine:
// a cell periodic in x, y and z with no walls and no gravity, consolidated by a servo on its
// height (x and y held) and sheared by its own deformation, the top image moving in +x over the
// bottom one at the wall's speed, the height servo-controlled (CNL) or held (CV). The engines
// (liggghts/periodic_cell_engine.hpp, yade/yade_periodic_cell.hpp) write the plate cell's raw
// columns: u_x the top image's travel, the "plate" the cell's height, both stresses the grains'.
#include "dem/scene/scene.hpp"
#include "io/csv_table.hpp"

namespace iwb::dem {

// The servo's gains (m/s per Pa): d(lz)/dt = k (sigma_zz - sigma_n0), capped at the scene's servo
// speed. Consolidating and relaxing, the plate cell's law with kp = 1: the top speed while the
// grains carry nothing, slowing in proportion as sigma_zz nears the target (k = vel_max /
// sigma_n0). (A gentler gain after the first approach, the trial's, left a loose cloud that had
// jammed for a moment at 27 kPa and let go at 4 Pa 48 windows later, never accepted; with one gain
// the truth grains' loose and dense cells are accepted after 5 and 13 windows.) Shearing, the gain
// moves the height per step by a share c of the correction a grain skeleton of modulus E would
// need, k = c H / (E dt), c = 0.6: the sheared skeleton is far softer than E and the height must
// follow the dilation. At c = 0.15 (the trial's 4e-6 m/s/Pa on the truth grains) sigma_n lagged
// 3 % above the target on average (smoke grains, dense, I 1e-3) and 3.6 % (truth grains); at 0.6
// by 0.8 %, every row within 1 %, no oscillation. Both engines apply the gain every step.
struct PeriodicServoGains {
  double consolidation, shear;
};
PeriodicServoGains periodic_servo_gains(const Scene& scene, double dt);

// The cloud's box height before consolidation: the requested grains at a loose solid fraction
// in the cell's x, y section less `margin` on every side (LIGGGHTS's insert/pack checks no overlap
// across a periodic face; YADE's placement does: margin 0), plus the margins.
double periodic_insertion_height(const Scene& scene, double margin);

// The whole cell is the band: the time series' e_band is its e_specimen.
void band_is_the_cell(io::CsvTable& timeseries);

}  // namespace iwb::dem
