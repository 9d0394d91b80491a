#pragma once
// The soil tests as the form limit's second judge (`iwb form-limit --soil-tests`, issue 59): per
// objective group, the residuals a material set leaves on them, so that the form limit can fit a
// wall only with sets the soil tests accept and say what every set costs there.
#include <string>
#include <vector>

#include "comparison/causes/form_limit.hpp"

namespace iwb::calibration {

// The soil tests of `dirs`, read now (a bad one is refused before the fit) with their seeds'
// scatter measured; the judge runs them with the model calibrate fits (vw3d) on the set's
// [hypoplastic] table. Empty `dirs`: no judge.
comparison::FormLimitOptions::SoilTests soil_test_judge(const std::vector<std::string>& dirs);

}  // namespace iwb::calibration
