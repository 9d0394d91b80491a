#pragma once
// One DEM run judged by one or several continuum models (`iwb compare RUN --model a,b`): one model
// into OUT, several each into OUT/<model>, so that an -igs model and its plain counterpart are
// judged along the same run (compare.hpp does each).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "comparison/compare/compare.hpp"

namespace iwb::comparison {

struct ModelComparisons {
  std::vector<std::filesystem::path> dirs;  // per model, in the order given
  std::vector<nlohmann::json> results;      // run_comparison's, per model
};

// `options` with every model of `models` in turn (options.out: OUT). Every model's inputs and
// directory are checked before any comparison is written: InputError for a model given twice, a
// form-limit record with several models, or a directory holding a comparison (unless force).
ModelComparisons compare_models(const CompareOptions& options,
                                const std::vector<std::string>& models);

}  // namespace iwb::comparison
