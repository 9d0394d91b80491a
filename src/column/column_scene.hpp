#pragma once
// A DEM scene as a column (issue 57: the column runs on a scene's soil and wall): the height
// between the wall and the plate's clamp, d50, the plate's boundary and the wall's travel from
// the scene; the wall's boundary from its R_n by the stated rule (src/column/README.md, "Which
// wall condition a DEM wall is"); e0 from the scene's DEM runs where they are given.
#include <filesystem>
#include <vector>

#include "column/column.hpp"
#include "dem/scene/scene.hpp"

namespace iwb::column {

// The wall's condition from its normalized roughness: the grains at the wall turn freely; no slip
// where R_n >= 0.5 (the DEM's grains trapped in the asperities move with the wall); below, the
// seed's kappa_r (eq. 5.35) and a slip at the critical simple-shear ratio of phi_r, sin phi_r =
// kappa_r sin phi_c. phi_c in rad.
struct ColumnWall {
  WallRotation rotation;
  double friction;  // tan(delta); infinite: no slip
};
ColumnWall wall_from_roughness(double R_n, double phi_c);

// `spec` (its soil, e0 and mesh density kept) on the scene's geometry, boundary, travel and wall;
// InputError for a cyclic scene (the column shears one way).
ColumnSpec on_scene(ColumnSpec spec, const dem::Scene& scene, double elements_per_d50);

// The mean void ratio of the runs' specimens at the start of shear (their timeseries.csv's first
// e_specimen); InputError naming a run that has none.
double start_void_ratio(const std::vector<std::filesystem::path>& runs);

// The travels (mm, ascending) of a DEM run's profile windows (its profiles.csv), those within
// `travel_mm`: the column writes its profiles there, to be set beside the run's. Empty where the
// run has no profiles.csv.
std::vector<double> profile_windows(const std::filesystem::path& run, double travel_mm);

}  // namespace iwb::column
