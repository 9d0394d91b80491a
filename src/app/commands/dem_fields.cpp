// `iwb dem fields RUN_DIR`: the coarse-grained continuum fields of a run's snapshots, again.
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "dem/analysis/run_fields.hpp"

namespace iwb::app {

namespace {
struct FieldsOptions {
  std::string run_dir;
  double width_d50 = 0.0;
  bool force = false;
};
}  // namespace

void add_dem_fields_command(CLI::App& dem, CommandList& commands) {
  auto o = std::make_shared<FieldsOptions>();
  auto* cmd = dem.add_subcommand("fields",
                                 "Coarse-grain a run's particle snapshots (vtk/particles_*.vtp, "
                                 "contacts_*.vtp) into continuum fields "
                                 "(Weinhart et al. 2012, Gaussian kernel of width w, y-averaged "
                                 "over the periodic cell): solid fraction, "
                                 "velocity, shear rate, vorticity, grain spin minus half the "
                                 "vorticity (the Cosserat rotation, large in a "
                                 "band), stress from the contacts plus the kinetic part "
                                 "(compression positive). Writes fields/fields_<step>.vti "
                                 "with fields/fields.pvd (open it in ParaView), "
                                 "fields/profile_<step>.csv (averaged over x and y), "
                                 "fields/band.csv (per snapshot: wall tau and sigma_n against the "
                                 "fields, mass balance, the band's void ratio) "
                                 "and fields/band_profile.csv (the second half of the travel), and "
                                 "the checks with tolerances and verdicts "
                                 "into summary.json under coarse_graining. `iwb dem run` does this "
                                 "when a run completes (scene: "
                                 "[coarse_graining] enabled, width_d50); run it here to redo it or "
                                 "to try another width. Snapshots already "
                                 "done are read back, not recomputed, unless --force.");
  cmd->add_option("run_dir", o->run_dir, "a run directory of `iwb dem run`")
      ->required()
      ->check(input_directory());
  cmd->add_option(
         "--width-d50", o->width_d50,
         "kernel width (the Gaussian's standard deviation) in d50; default: the scene's, else 0.5. "
         "A new width recomputes every snapshot")
      ->check(number_in({0.0, kMaxCellSizeD50, true}, "d50"));
  cmd->add_flag("--force", o->force, "recompute every snapshot");
  commands.add(cmd, [o](const CommandContext&) {
    dem::RunFieldsOptions opt;
    if (o->width_d50 > 0.0) opt.width_d50 = o->width_d50;
    opt.force = o->force || o->width_d50 > 0.0;
    opt.progress = engine_progress();
    const auto result = dem::coarse_grain_run(o->run_dir, opt);
    fmt::print("{}\n", result.dump(2));
    return result.value("verdict", "") == "all checks pass" ? 0 : 1;
  });
}

}  // namespace iwb::app
