#pragma once
// The coarse-graining of a run directory (issue 21): every vtk/particles_<step>.vtp with its
// contacts_<step>.vtp becomes fields/fields_<step>.vti (the x-z image, averaged over y) and
// fields/profile_<step>.csv (the height profile, averaged over x and y), indexed by
// fields/fields.pvd; fields/band.csv follows the balance checks and the band's void ratio snapshot
// by snapshot, and fields/band_profile.csv is the profile averaged over the second half of the
// travel. The checks with their tolerances and verdicts go to summary.json under "coarse_graining".
// It knows the run directory's contract only (DEM.md), not the engine that wrote it.
//
// Resumable: a snapshot whose .vti and profile exist is read back, not computed again (--force
// recomputes). Nothing is written if the run directory is not one (InputError, exit 2).
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace iwb::dem {

struct RunFieldsOptions {
  std::optional<double> width_d50;  // else the scene's [coarse_graining] width_d50
  bool force = false;
  std::function<void(const std::string&)> progress;
};

// Returns the "coarse_graining" entry written to summary.json.
nlohmann::json coarse_grain_run(const std::filesystem::path& run_dir,
                                const RunFieldsOptions& options);

}  // namespace iwb::dem
