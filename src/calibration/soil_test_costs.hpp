#pragma once
// What a form limit's material set costs on the soil tests (`iwb form-limit --soil-tests`): each
// objective group's RMS with the soil-test set and with the form limit's, rows for its report.
#include <string>
#include <vector>

#include "comparison/form_limit.hpp"

namespace iwb::calibration {

// The soil tests of `dirs`, read now (a bad one is refused before the fit) with their seeds'
// scatter measured, judged later by the form limit with both sets; empty `dirs`: no judgement.
// The soil model is the one calibrate fits (vw3d) on the same [hypoplastic] table.
comparison::FormLimitOptions::Elsewhere soil_test_costs(const std::vector<std::string>& dirs);

}  // namespace iwb::calibration
