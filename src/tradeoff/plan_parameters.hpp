#pragma once
// `iwb plan` from its files (plan.hpp): the parameter sets read from --params (the first for every
// model, the others further calibrations), or, when none is given, the set `iwb validate` would
// choose for the tradeoff's reference run from those built into iwb
// (validation/parameter_choice.hpp).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tradeoff/plan.hpp"

namespace iwb::tradeoff {

// run_plan with `options`' params, params_why and other_calibrations from `files`. The scene and
// its [requirements] are checked before the tradeoff is read, the files before anything runs.
nlohmann::json run_plan_from_files(PlanOptions options, const std::vector<std::string>& files);

}  // namespace iwb::tradeoff
