#pragma once
// `iwb validate`, the README's main job (issue 6): run a scene in each DEM engine asked for (the
// embedded default scene in LIGGGHTS unless told otherwise), replay it through hvwe with the shipped parameter set that best
// matches the DEM's grains, and write the HTML report.
#include <filesystem>
#include <string>
#include <vector>

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

}  // namespace iwb::app
