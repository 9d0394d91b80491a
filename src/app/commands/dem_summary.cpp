// `iwb dem summary RUN_DIR`: a run's derived quantities recomputed from its contract files.
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "dem/run/run.hpp"
#include "dem/soil_cells/soil_cell.hpp"
#include "io/json_file.hpp"

namespace iwb::app {

void add_dem_summary_command(CLI::App& dem, CommandList& commands) {
  auto run_dir = std::make_shared<std::string>();
  auto* dem_summary = dem.add_subcommand(
      "summary",
      "Recompute summary.json of a complete run directory from its contract files (peak and "
      "residual friction, dilation, shear mode and band, wall slip, band void ratio); for a "
      "simple-shear soil cell of `iwb dem soiltest`, its manifest's cell_summary.");
  dem_summary->add_option("run_dir", *run_dir, "a run directory of `iwb dem run` or `dem soiltest`")
      ->required()
      ->check(input_directory());
  commands.add(dem_summary, [run_dir](const CommandContext&) {
    const auto manifest = std::filesystem::path(*run_dir) / "manifest.json";
    const bool cell = std::filesystem::is_regular_file(manifest) &&
                      io::read_json_file(manifest).value("kind", std::string()) == "soiltest";
    fmt::print("{}\n",
               (cell ? dem::resummarize_cell(*run_dir) : dem::resummarize(*run_dir)).dump(2));
    return 0;
  });
}

}  // namespace iwb::app
