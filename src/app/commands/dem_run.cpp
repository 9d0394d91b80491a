// `iwb dem run SCENE.toml`: a DEM interface-shear scene into a run directory (dem/run/run.hpp).
#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "dem/engines/engines.hpp"
#include "dem/run/consolidation_cache.hpp"
#include "dem/run/run.hpp"
#include "io/run_directory.hpp"

namespace iwb::app {

namespace {

struct DemRunOptions {
  std::string scene_file, engine_name = "liggghts", out, consolidated;
  int np = 1;
  bool resume = false, force = false;
};

int run_dem(const DemRunOptions& o, const CommandContext& context) {
  const auto scene = dem::load_scene(o.scene_file);  // refused here, before any engine starts
  for (const auto& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  const auto engine = dem::make_engine(o.engine_name);
  const auto dir = o.out.empty() ? std::filesystem::path("runs") /
                                       fmt::format("{}-{}", scene.name, o.engine_name)
                                 : std::filesystem::path(o.out);
  dem::RunOptions opt{dir,
                      o.np,
                      o.resume,
                      o.force,
                      context.command_line,
                      context.interrupt,
                      engine_progress(),
                      dem::consolidation_cache_dir(o.consolidated)};
  fmt::print(stderr, "iwb dem run: {} with {} ({} particles requested, {} rank(s)) -> {}\n",
             o.scene_file, o.engine_name, scene.particle_count, o.np, dir.string());
  const auto outcome = dem::run_scene(scene, io::read_file(o.scene_file), *engine, opt);
  fmt::print(outcome.complete() ? stdout : stderr, "{}: {} -> {}\n", o.scene_file, outcome.status,
             dir.string());
  return outcome.complete() ? 0 : 1;
}

}  // namespace

void add_dem_run_command(CLI::App& dem, CommandList& commands) {
  auto o = std::make_shared<DemRunOptions>();
  auto* dem_run = dem.add_subcommand(
      "run",
      "Run a scene in a DEM engine and write the run directory of the contract (DEM.md): "
      "manifest.json, timeseries.csv, profiles.csv, vtk/ with .pvd indexes, summary.json. Stages "
      "(consolidate, shear) are recorded as they finish; --resume continues an interrupted run, a "
      "LIGGGHTS shear stage from its last checkpoint (written every ~1/50 of the stage).");
  dem_run->add_option("scene", o->scene_file, "scene TOML file")->required()->check(input_file());
  dem_run->add_option("--engine", o->engine_name, "DEM engine: liggghts or yade")
      ->capture_default_str();
  dem_run
      ->add_option("--np,--threads", o->np,
                   "parallel processes: MPI ranks (LIGGGHTS) or OpenMP threads (YADE)")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  dem_run->add_option("--out,-o", o->out, "run directory (default runs/<scene>-<engine>)")
      ->check(output_directory());
  dem_run->add_flag(
      "--resume", o->resume,
      "continue an interrupted run of the same scene from its last finished stage (LIGGGHTS: "
      "a shear stage from its last checkpoint, if this iwb wrote it)");
  dem_run->add_flag("--force", o->force, "replace an earlier run in the same directory");
  dem_run->add_option(
      "--consolidated", o->consolidated,
      "start from a consolidated specimen of the same consolidation key kept in DIR, or keep this "
      "run's there (default $IWB_CONSOLIDATED_DIR, else none; "
      "src/dem/run/consolidation_cache.hpp)");
  commands.add(dem_run, [o](const CommandContext& c) { return run_dem(*o, c); });
}

}  // namespace iwb::app
