#include "dem/scene/scene_roughness.hpp"

#include <fmt/core.h>

#include "walls/descriptors.hpp"

namespace iwb::dem {

nlohmann::json scene_roughness(const Scene& s) {
  const double d50 = s.particles.d50_m;
  nlohmann::json j;
  for (const auto& [name, profile] : {std::pair{"wall", &s.wall}, std::pair{"plate", &s.plate}})
    j[name] = walls::to_json(walls::describe_roughness(*profile, s.length_m, s.width_m, d50), d50);
  return j;
}

std::string scene_roughness_text(const Scene& s) {
  const double d50 = s.particles.d50_m;
  std::string out = fmt::format("{}: d50 {:g} mm, box {:g} x {:g} d50\n", s.source, d50 * 1e3,
                                s.length_m / d50, s.width_m / d50);
  for (const auto& [name, profile] : {std::pair{"wall", &s.wall}, std::pair{"plate", &s.plate}})
    out += fmt::format(
        "{} ({}):\n{}", name, profile->describe(),
        walls::to_text(walls::describe_roughness(*profile, s.length_m, s.width_m, d50), d50));
  return out;
}

}  // namespace iwb::dem
