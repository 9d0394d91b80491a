#pragma once
// From an engine's raw outputs to the run-directory contract (DEM.md), once for all engines: both
// runners write timeseries.raw with the same columns (SI) and report height bins of the profile,
// so the unit conversion, the bin smoothing and the servo's report card live
// here. An engine's own code only parses what its output format makes different.
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/engines/engine.hpp"
#include "dem/scene/numerics.hpp"

namespace iwb::dem {

// Whitespace-separated numbers per line; comments (#) and text lines skipped.
std::vector<std::vector<double>> numeric_lines(const std::filesystem::path& path);

// timeseries.raw columns: t ux zplate sigma_wall tau_wall sigma_plate vsolid vband coordination
// atoms ke (SI). z0 is the plate height when shear starts. A row whose time is not after the row
// before replaces the rows from its time on (a resumed attempt's rows after a stopped one's).
io::CsvTable timeseries_table(const Scene& s, const Numerics& n, const std::filesystem::path& raw,
                              double z0);

// One height bin of one profile window, SI, stresses compression positive and per bin volume.
struct ProfileBin {
  double z_over_d50;  // above the wall's mean surface
  double count, vx, solid, szz, sxz;
};
using ProfileBlocks = std::map<long, std::vector<ProfileBin>>;  // by engine step

io::CsvTable profile_table(const Scene& s, const Numerics& n, const ProfileBlocks& blocks,
                           long step0);

// How well the plate did what the boundary condition asks, from the time series.
nlohmann::json plate_facts(const Scene& s, const io::CsvTable& timeseries);

}  // namespace iwb::dem
