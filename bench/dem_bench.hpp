#pragma once
// `iwb bench dem`: particle-steps per second of a DEM engine on a scene (the default scene unless
// given) with 1 and 2 ranks, and the workbench's own overhead (input generation, output parsing,
// contract assembly, summary) as a share of the run. Prints figures; asserts nothing.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iwb::bench {

struct DemBenchOptions {
  std::string scene = "data/scenes/default.toml";
  std::string engine = "liggghts";
  std::vector<int> ranks = {1, 2};
};

nlohmann::json run_dem_bench(const DemBenchOptions& options);

}  // namespace iwb::bench
