// `iwb dem keys`: every key a scene file may hold, from the declarations the parser reads
// (src/dem/scene/scene_keys.cpp); data/scenes/README.md's key table is this command's Markdown.
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "dem/scene/scene_keys.hpp"

namespace iwb::app {

void add_dem_keys_command(CLI::App& dem, CommandList& commands) {
  auto format = std::make_shared<std::string>("markdown");
  auto* keys = dem.add_subcommand(
      "keys",
      "List every key a scene file may hold: its table, what values it allows, its default and "
      "what it means (the table of data/scenes/README.md, generated from the same declarations "
      "the scene parser reads).");
  keys->add_option("--format", *format, "markdown (a table) or json (one object per key)")
      ->check(CLI::IsMember({"markdown", "json"}));
  commands.add(keys, [format](const CommandContext&) {
    const auto& rows = dem::scene_keys();
    fmt::print("{}",
               *format == "json" ? io::to_json(rows).dump(2) + "\n" : io::markdown_table(rows));
    return 0;
  });
}

}  // namespace iwb::app
