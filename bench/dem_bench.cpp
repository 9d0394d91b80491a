#include "bench/dem_bench.hpp"

#include <fmt/core.h>

#include <chrono>
#include <filesystem>

#include "common/errors.hpp"
#include "dem/analysis/run_fields.hpp"
#include "dem/engines/engines.hpp"
#include "dem/run/run.hpp"
#include "io/run_directory.hpp"

namespace iwb::bench {

namespace {

struct FieldsCost {
  double per_snapshot_s, engine_per_snapshot_s;
};

// The coarse-graining of the run's snapshots timed on its own, against the engine's time to
// produce a snapshot (the shear stage's loop time over the intervals between snapshots).
FieldsCost fields_cost(const std::filesystem::path& dir, const nlohmann::json& manifest) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto fields = dem::coarse_grain_run(dir, {std::nullopt, true, nullptr});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double snapshots = fields.value("snapshots", 1.0);
  const double shear = manifest["stages"]["shear"]["facts"].value("engine_loop_seconds", 0.0);
  return {seconds / snapshots, shear / std::max(1.0, snapshots - 1.0)};
}

}  // namespace

nlohmann::json run_dem_bench(const DemBenchOptions& opt) {
  dem::make_engine(opt.engine);  // an unknown engine is refused before anything runs
  const std::string text = io::read_file(opt.scene);
  const auto scene = dem::parse_scene(text, opt.scene);
  fmt::print("iwb bench dem: {} in {} ({} particles requested), one full run per rank count\n\n",
             opt.scene, opt.engine, scene.particle_count);
  fmt::print("{:>5} {:>10} {:>14} {:>12} {:>16} {:>16} {:>16} {:>10} {:>12} {:>10} {:>14} {:>14}\n",
             "ranks", "particles", "particle-steps", "engine loop s", "particle-steps/s",
             "consolidation/s", "shear/s", "total s", "workbench s", "share", "cg s/snapshot",
             "shear s/snapshot");
  nlohmann::json out = nlohmann::json::array();
  const auto tmp =
      std::filesystem::temp_directory_path() / fmt::format("iwb-bench-dem-{}", ::getpid());
  for (int np : opt.ranks) {
    const auto engine = dem::make_engine(opt.engine);
    const auto dir = tmp / fmt::format("np{}", np);
    const auto t0 = std::chrono::steady_clock::now();
    const auto outcome =
        dem::run_scene(scene, text, *engine, {dir, np, false, true, "bench", nullptr, nullptr, {}});
    const double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!outcome.complete())
      throw std::runtime_error(fmt::format("bench run failed: {}", outcome.status));
    double loop = 0, steps = 0, process = 0, generation = 0;
    nlohmann::json per_stage =
        nlohmann::json::object();  // a stage whose ranks are unbalanced shows here
    for (const auto& [name, stage] : outcome.manifest["stages"].items()) {
      const double stage_loop = stage["facts"].value("engine_loop_seconds", 0.0);
      const double stage_steps = stage["facts"].value("particle_steps", 0.0);
      per_stage[name] = stage_loop > 0.0 ? stage_steps / stage_loop : 0.0;
      loop += stage_loop;
      steps += stage_steps;
      generation += stage["facts"].value("generation_seconds", 0.0);
      process += stage.value("wall_seconds", 0.0) - stage["facts"].value("generation_seconds", 0.0);
    }
    // The workbench's own time: generating inputs, and everything outside the engine process
    // (following its output is done while it runs and costs no wall time of its own).
    const double workbench = total - process;
    const FieldsCost cg = fields_cost(dir, outcome.manifest);
    fmt::print(
        "{:>5} {:>10} {:>14.4g} {:>12.2f} {:>16.3g} {:>16.3g} {:>16.3g} {:>10.2f} {:>12.3f} "
        "{:>9.2f}% {:>14.3f} {:>14.2f}\n",
        np, outcome.manifest.value("particle_count", 0), steps, loop, steps / loop,
        per_stage.value("consolidate", 0.0), per_stage.value("shear", 0.0), total, workbench,
        100.0 * workbench / total, cg.per_snapshot_s, cg.engine_per_snapshot_s);
    out.push_back({{"ranks", np},
                   {"particle_steps", steps},
                   {"engine_loop_seconds", loop},
                   {"particle_steps_per_second", steps / loop},
                   {"particle_steps_per_second_by_stage", per_stage},
                   {"total_seconds", total},
                   {"workbench_seconds", workbench},
                   {"generation_seconds", generation},
                   {"coarse_graining_seconds_per_snapshot", cg.per_snapshot_s},
                   {"shear_engine_seconds_per_snapshot", cg.engine_per_snapshot_s}});
  }
  std::filesystem::remove_all(tmp);
  fmt::print(
      "\nengine loop: the engine's own time in its run loops (IWB_COST: LIGGGHTS' 'Loop time', "
      "YADE's O.run); total: the whole `iwb dem run`; workbench: total\n"
      "minus the engine processes (input generation, output parsing, contract assembly, summary, "
      "coarse-graining);\n"
      "cg s/snapshot: `iwb dem fields --force` per particle snapshot (x-z image, profile, checks); "
      "shear s/snapshot:\n"
      "the engine's shear-stage loop time between two snapshots\n");
  return out;
}

}  // namespace iwb::bench
