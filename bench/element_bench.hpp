#pragma once
// `iwb bench element`: the cost of the continuum core. For each model: rate evaluations per
// second (double and dual numbers) on a sheared state, and the wall time of a 2000-increment CNL
// simple shear (d gamma = 1e-4) at relative tolerance 1e-6. Prints figures; asserts nothing.
// Models that need tables seed Table 5.1 lacks (the -igs models) run on `igs_params`, or are
// skipped with a note when that file is not there.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iwb::bench {

struct ElementBenchOptions {
  int repeats = 5;  // the test time is the best of these
  // Seed Table 5.3 Toyoura: the set of the seed's intergranular-strain examples (5.7.5).
  std::filesystem::path igs_params = "data/params/table_5_3_toyoura.toml";
  std::vector<std::string> models;  // only these (names of `iwb models`); empty: every model
};

nlohmann::json run_element_bench(const ElementBenchOptions& options);

}  // namespace iwb::bench
