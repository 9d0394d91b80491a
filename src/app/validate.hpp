#pragma once
// `iwb validate`, the README's main job (issue 6): run a scene in each DEM engine asked for (the
// embedded default scene in LIGGGHTS unless told otherwise), replay it through hvwe with the
// parameter set calibrated on the scene's grains if there is one (data/params/dem_default_grains.toml
// for the default scene's grains, issue 7), else the shipped set whose phi_c is closest to the
// DEM's residual friction angle, and write the HTML report.
#include <filesystem>
#include <string>
#include <vector>

#include "dem/scene.hpp"

namespace iwb::app {

struct ValidateOptions {
  std::string scene = "default";  // an embedded scene name or a scene file
  std::vector<std::string> engines = {"liggghts"};  // each runs the scene; one report
  int processes = 2;
  std::filesystem::path out = "runs/validate";
  std::filesystem::path params_dir = "data/params";
  bool force = false;
  std::string command_line;
};

int run_validate(const ValidateOptions& options);

// The shipped parameter set in `dir` whose critical friction angle is closest to the DEM's
// residual interface friction angle atan(residual_friction); `why` says so. Also `iwb plan`'s default.
std::filesystem::path matching_parameters(const std::filesystem::path& dir, double residual_friction, std::string& why);

// The set for a DEM run of `scene`: the one calibrated on the scene's grains if there is one
// (data/calibration/), else matching_parameters. `iwb validate` and `iwb plan` choose with it.
std::filesystem::path parameters_for(const std::filesystem::path& dir, const dem::Scene& scene, double residual_friction,
                                     std::string& why);

}  // namespace iwb::app
