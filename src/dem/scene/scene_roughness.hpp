#pragma once
// The roughness descriptors of a scene's wall and plate (src/walls/descriptors.hpp) over its box:
// in every run's manifest (`roughness`) and printed by `iwb dem roughness SCENE`.
#include <nlohmann/json.hpp>
#include <string>

#include "dem/scene/scene.hpp"

namespace iwb::dem {

nlohmann::json scene_roughness(const Scene& scene);  // {"wall": {...}, "plate": {...}}
std::string scene_roughness_text(const Scene& scene);

}  // namespace iwb::dem
