// `iwb dem crosscheck SCENE.toml --seeds K`: one scene in both engines (dem/run/crosscheck.hpp).
#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "dem/run/crosscheck.hpp"
#include "io/run_directory.hpp"

namespace iwb::app {

namespace {

struct CrosscheckCommand {
  dem::CrosscheckOptions options;
  std::string scene, out, engines = "liggghts,yade";
};

int run_crosscheck(const CrosscheckCommand& o, const CommandContext& context) {
  auto opt = o.options;
  opt.scene_file = o.scene;
  opt.engines = split_list(o.engines);
  opt.out = o.out.empty() ? std::filesystem::path("runs") /
                                ("crosscheck-" + std::filesystem::path(o.scene).stem().string())
                          : std::filesystem::path(o.out);
  opt.command_line = context.command_line;
  opt.interrupt = context.interrupt;
  opt.progress = engine_progress();
  dem::run_crosscheck(opt);
  fmt::print("{}", io::read_file(opt.out / "crosscheck.md"));
  fmt::print("-> {}\n", opt.out.string());
  return 0;
}

}  // namespace

void add_dem_crosscheck_command(CLI::App& dem, CommandList& commands) {
  auto o = std::make_shared<CrosscheckCommand>();
  auto* dem_cross = dem.add_subcommand(
      "crosscheck",
      "Run one scene in both engines with K seeds each (seed = 1..K) and put peak and residual "
      "tau/sigma_n, total dilation, dilation rate and wall band thickness side by side with their "
      "seed scatter and each engine's wall-clock cost. Per quantity: do the engines agree within "
      "their seed scatter (the difference of the means within 2 standard errors, sqrt(sd_a^2/n_a + "
      "sd_b^2/n_b); needs 2 seeds or more)? Verdicts: residual friction within 10 %, dilation of "
      "the "
      "same sign and order. Writes crosscheck.json and crosscheck.md; complete runs in the output "
      "directory are reused, so a stopped crosscheck continues when run again.");
  dem_cross->add_option("scene", o->scene, "scene TOML file")->required()->check(input_file());
  dem_cross->add_option("--seeds", o->options.seeds, "seeds per engine")
      ->check(whole_in(1, 100))
      ->capture_default_str();
  dem_cross->add_option("--engines", o->engines, "comma-separated engines")->capture_default_str();
  dem_cross
      ->add_option("--np,--threads", o->options.processes, "MPI ranks / OpenMP threads per run")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  dem_cross->add_option("--out,-o", o->out, "output directory (default runs/crosscheck-<scene>)")
      ->check(output_directory());
  commands.add(dem_cross, [o](const CommandContext& c) { return run_crosscheck(*o, c); });
}

}  // namespace iwb::app
