// `iwb dem summary RUN_DIR`: a run's derived quantities recomputed from its contract files.
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "dem/run.hpp"

namespace iwb::app {

void add_dem_summary_command(CLI::App& dem, CommandList& commands) {
  auto run_dir = std::make_shared<std::string>();
  auto* dem_summary = dem.add_subcommand(
      "summary",
      "Recompute summary.json of a complete run directory from its contract files (peak and "
      "residual friction, dilation, shear mode and band, wall slip, band void ratio).");
  dem_summary->add_option("run_dir", *run_dir, "a run directory of `iwb dem run`")
      ->required()
      ->check(input_directory());
  commands.add(dem_summary, [run_dir](const CommandContext&) {
    fmt::print("{}\n", dem::resummarize(*run_dir).dump(2));
    return 0;
  });
}

}  // namespace iwb::app
