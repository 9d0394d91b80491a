#pragma once
// Which parameter set replays a DEM run of a scene (issues 6 and 7), for `iwb validate` and
// `iwb plan`: the set calibrated on the scene's grains if there is one (dem_default_grains.toml for
// the default scene's grains, data/calibration/dem_default_grains/), else the set whose critical
// friction angle is closest to the DEM's residual interface friction angle. The sets come from
// io::parameter_sets: built into the binary, or a directory given with --params-dir.
#include <string>
#include <vector>

#include "dem/scene/scene.hpp"
#include "io/parameter_sets.hpp"

namespace iwb::validation {

// The set calibrated on the scene's grains, or nullptr if none of `sets` is; `why` says so.
const io::ParameterSet* calibrated_parameters(const std::vector<io::ParameterSet>& sets,
                                              const dem::Scene& scene, std::string& why);

// The set (calibrated ones excepted: they stand for their own grains only) whose phi_c is closest
// to atan(residual_friction); `why` says so. InputError when no set has [hypoplastic] phi_c_deg.
const io::ParameterSet& matching_parameters(const std::vector<io::ParameterSet>& sets,
                                            double residual_friction, std::string& why);

// calibrated_parameters, else matching_parameters.
const io::ParameterSet& parameters_for(const std::vector<io::ParameterSet>& sets,
                                       const dem::Scene& scene, double residual_friction,
                                       std::string& why);

// InputError (naming where the sets came from) unless some set can be matched by phi_c: checked
// before a DEM run whose result the choice waits for.
void require_matchable(const std::vector<io::ParameterSet>& sets, const std::string& where);

}  // namespace iwb::validation
