#pragma once
// `iwb validate`, the README's main job (issue 6): run a scene in each DEM engine asked for (the
// embedded default scene in LIGGGHTS unless told otherwise), replay it through hvwe with the
// parameter set validation/parameter_choice.hpp picks, and write the HTML report.
//
// It runs from any directory: the scenes and parameter sets are built into the binary. Everything
// is resolved and checked before an engine starts (engines, scene, parameter sets, what each run
// directory holds). A complete DEM run of the same scene content in the output directory is reused
// and a stopped one of the same scene text resumed, so a second call, with other --params-dir too,
// redoes only the replay and the report (seconds); --force runs the DEM again.
#include <filesystem>
#include <string>
#include <vector>

namespace iwb::validation {

struct ValidateOptions {
  std::string scene = "default";                    // an embedded scene name or a scene file
  std::vector<std::string> engines = {"liggghts"};  // each runs the scene; one report
  int processes = 2;
  std::filesystem::path out = "runs/validate";
  std::filesystem::path params_dir;  // empty: the parameter sets built into iwb
  bool force = false;
  std::string command_line;
};

int run_validate(const ValidateOptions& options);

}  // namespace iwb::validation
