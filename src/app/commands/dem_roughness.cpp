// `iwb dem roughness SCENE`: the roughness descriptors of a scene's wall and plate (issue 36).
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "dem/scene/scene_roughness.hpp"

namespace iwb::app {

void add_dem_roughness_command(CLI::App& dem, CommandList& commands) {
  auto scene = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("text");
  auto* cmd = dem.add_subcommand("roughness",
                                 "Describe a scene's wall and plate: R_n = R_max(d50)/d50 (largest "
                                 "and mean over gauge windows), R_max, R_a, "
                                 "R_q, the mean slope |dz/dx|, the correlation length, the power "
                                 "spectrum along x and, where the surface is "
                                 "self-affine, its Hurst exponent (src/walls/descriptors.hpp says "
                                 "how each is computed). No engine runs; "
                                 "every run's manifest holds the same under `roughness`.");
  cmd->add_option("scene", *scene, "a scene file (data/scenes/README.md)")
      ->required()
      ->check(input_file());
  cmd->add_option("--format", *format, "text (default) or json")
      ->check(CLI::IsMember({"text", "json"}));
  commands.add(cmd, [scene, format](const CommandContext&) {
    const auto s = dem::load_scene(*scene);
    fmt::print("{}", *format == "json" ? dem::scene_roughness(s).dump(2) + "\n"
                                       : dem::scene_roughness_text(s));
    return 0;
  });
}

}  // namespace iwb::app
