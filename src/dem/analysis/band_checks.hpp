#pragma once
// The checks the coarse-grained fields make possible (issue 21), per run: the momentum balance
// (the shear stress uniform across the height and equal to the wall's tau; the normal stress equal
// to the wall's sigma_n), the mass balance (the solid fraction integrates to the grains' volume),
// the band's thickness from the coarse-grained velocity against the grains' own velocities binned
// by centre in the same snapshot, and the band's void ratio snapshot by snapshot. Each check has a
// tolerance and a verdict.
#include <nlohmann/json.hpp>
#include <vector>

#include "coarse_graining/band_measures.hpp"
#include "dem/scene/numerics.hpp"
#include "dem/scene/scene.hpp"
#include "io/csv_table.hpp"

namespace iwb::dem {

struct SnapshotProfile {
  double time_s;            // since the start of shear
  io::CsvTable profile;     // run_fields.hpp's profile_<step>.csv
  double grains_volume_m3;  // sum of the grains' volumes
  // the grains' v_x / v_wall binned by centre (scene's profile_bin_d50), heights in d50 above the
  // wall's mean height as the profile's: the kernel-free velocity of the same instant
  coarse_graining::BinnedProfile grain_velocity;
};

struct BandChecks {
  io::CsvTable per_snapshot;  // fields/band.csv
  io::CsvTable mean_profile;  // fields/band_profile.csv: the second half of the travel
  nlohmann::json json;        // summary.json's "coarse_graining"
};

BandChecks band_checks(const dem::Scene& scene, const dem::Numerics& numerics,
                       const io::CsvTable& timeseries, const std::vector<SnapshotProfile>& profiles,
                       double width_m);

}  // namespace iwb::dem
