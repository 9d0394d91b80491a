// `iwb run`: the continuum study on seed Table 5.1 (app/default_job.hpp).
#include <memory>
#include <string>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/default_job.hpp"
#include "app/option_checks.hpp"

namespace iwb::app {

namespace {
struct RunOptions {
  std::string out = "runs/default";
  bool force = false;
};
}  // namespace

void add_run_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<RunOptions>();
  auto* run = app.add_subcommand(
      "run", "The main job on the embedded default: hvwe against its 3D reference vw3d in simple "
             "shear under CNL, CNS and CV (seed Table 5.1), with a table of their differences.");
  run->add_option("--out,-o", o->out, "output directory")->check(output_directory())->capture_default_str();
  run->add_flag("--force", o->force, "replace earlier runs in the output directory");
  commands.add(run, [o](const CommandContext& c) { return run_default_job(o->out, o->force, c.command_line); });
}

}  // namespace iwb::app
