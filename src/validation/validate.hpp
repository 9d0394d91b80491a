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
#include <functional>
#include <string>
#include <vector>

namespace iwb::validation {

// A line for the caller to show (no newline); the job itself prints nothing.
using Lines = std::function<void(const std::string&)>;

struct ValidateOptions {
  std::string scene = "default";                    // an embedded scene name or a scene file
  std::vector<std::string> engines = {"liggghts"};  // each runs the scene; one report
  int processes = 2;
  std::filesystem::path out = "runs/validate";
  std::filesystem::path params_dir;  // empty: the parameter sets built into iwb
  bool force = false;
  std::string command_line;
  Lines warning = [](const std::string&) {};      // the scene's, once it is checked
  Lines step = [](const std::string&) {};         // each step as it starts, and a run that failed
  Lines engine_line = [](const std::string&) {};  // every line of a running engine
};

struct ValidateOutcome {
  bool complete = false;         // false: a DEM run did not complete (`step` said why), no report
  std::filesystem::path report;  // OUT/report.html
};

// InputError, before anything runs or is written, for a bad engine, scene, parameter directory or
// an output directory holding another run.
ValidateOutcome run_validate(const ValidateOptions& options);

}  // namespace iwb::validation
