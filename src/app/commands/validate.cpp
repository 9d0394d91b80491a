// `iwb validate`: the main job, a DEM scene replayed through hvwe into one report
// (validation/validate.hpp).
#include "validation/validate.hpp"

#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"

namespace iwb::app {

namespace {
struct ValidateCommand {
  validation::ValidateOptions options;
  std::string out = "runs/validate", engines = "liggghts";
};

// The job's steps and the engines' lines on stderr as it goes, the report's path on stdout.
int run_validate_command(validation::ValidateOptions opt) {
  opt.warning = [](const std::string& w) { fmt::print(stderr, "warning: {}\n", w); };
  opt.step = [](const std::string& s) { fmt::print(stderr, "iwb validate: {}\n", s); };
  opt.engine_line = sparse_engine_progress();
  const auto outcome = validation::run_validate(opt);
  if (!outcome.complete) return 1;
  fmt::print("report: {}\n", std::filesystem::absolute(outcome.report).string());
  return 0;
}

}  // namespace

void add_validate_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<ValidateCommand>();
  auto* validate = app.add_subcommand(
      "validate",
      "The main job: run a DEM scene (the embedded default unless --scene), replay it through hvwe "
      "with the set calibrated on the scene's grains (data/calibration/) or else the shipped set "
      "closest to the DEM's residual friction angle, and write "
      "report.html (a few minutes on 2 cores). Runs from any directory: the scenes (data/scenes/"
      "default.toml, smoke.toml) and parameter sets (data/params/) are built into iwb. Everything "
      "is "
      "checked before the engine starts. Run again with the same scene and --out, it reuses the "
      "complete DEM run there (a stopped one is resumed) and redoes only the replay and the "
      "report, "
      "also with another --params-dir; --force runs the DEM again.");
  auto& vopt = o->options;
  validate
      ->add_option("--scene", vopt.scene, "embedded scene name (default, smoke) or a scene file")
      ->capture_default_str();
  validate
      ->add_option("--engines", o->engines,
                   "comma-separated DEM engines (liggghts, yade); each runs the scene and is "
                   "replayed, one report")
      ->capture_default_str();
  validate
      ->add_option("--np,--threads", vopt.processes,
                   "MPI ranks (LIGGGHTS) or threads (YADE) per run")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  validate->add_option("--out,-o", o->out, "output directory")
      ->check(output_directory())
      ->capture_default_str();
  validate
      ->add_option("--params-dir", vopt.params_dir,
                   "a directory of parameter sets (*.toml) to choose from "
                   "instead of those built into iwb (data/params/ at build time)")
      ->check(input_directory());
  validate->add_flag("--force", vopt.force, "replace earlier runs in the output directory");
  commands.add(validate, [o](const CommandContext& c) {
    auto opt = o->options;
    opt.out = o->out;
    opt.engines = split_list(o->engines);
    opt.command_line = c.command_line;
    return run_validate_command(opt);
  });
}

}  // namespace iwb::app
