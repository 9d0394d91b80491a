#pragma once
// The start-up ramp of a scene's shear as the manifest's numerics record it
// (dem/scene/shear_start.hpp has the physics; this reads the scene it was derived into).
#include <nlohmann/json.hpp>

#include "dem/scene/scene.hpp"

namespace iwb::dem {

// Rule, c_s, time, displacement and steps at dt.
nlohmann::json ramp_numerics(const Scene& s, double dt);

}  // namespace iwb::dem
