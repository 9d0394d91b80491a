#pragma once
// `iwb compare --runs DIR...`: every DEM run of a set compared (or an earlier complete comparison
// of the same inputs reused) into OUT/<run name>, with the runs of the set that are its scene with
// other seeds as its seeds (comparison/replay/seed_scatter.hpp), then the hypothesis checks over
// the set into OUT/hypotheses.json and OUT/hypotheses.md, with OUT/manifest.json saying what was
// done.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "comparison/compare/compare.hpp"
#include "comparison/compare/hypotheses.hpp"
#include "models/registry.hpp"

namespace iwb::comparison {

struct RunSetOptions {
  std::vector<std::filesystem::path> dem_dirs;
  std::string model = models::kDefaultInterfaceModel;
  std::string params;
  std::filesystem::path out;
  bool allow_partial = false;
  bool force = false;  // replace complete comparisons of other inputs
  std::string command_line;
  double predicted_ds_d50 = kDefaultPredictedDsD50;
  std::filesystem::path form_limit;   // CompareOptions::form_limit
  std::string roughness_scheme, f_c;  // CompareOptions' (empty: the model's defaults)
  bool pool_scatter = true;           // pool the seed scatter across cells where Levene allows
};

struct RunSetOutcome {
  std::vector<std::filesystem::path> compare_dirs;
  std::vector<std::string> reused;  // names of the runs whose comparison was reused
  nlohmann::json hypotheses;        // as written to hypotheses.json
};

RunSetOutcome run_hypothesis_set(const RunSetOptions& options);

// The record of one comparison directory: compare.json's fit and the DEM's summary.json.
RunRecord load_run_record(const std::filesystem::path& compare_dir);

}  // namespace iwb::comparison
