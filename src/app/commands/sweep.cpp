// `iwb sweep SWEEP.toml`: a campaign of DEM runs, then its verdicts (campaign/sweep.hpp).
#include <fmt/core.h>

#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "campaign/sweep.hpp"

namespace iwb::app {

namespace {

struct SweepCommand {
  campaign::SweepOptions options;
  std::string sweep_file, out, emit;
};

// The campaign, then its verdicts when it names a comparison.
int run_sweep(const SweepCommand& o, const CommandContext& context) {
  auto opt = o.options;
  opt.sweep_file = o.sweep_file;
  opt.out = o.out;
  opt.emit_slurm = o.emit == "slurm";
  opt.command_line = context.command_line;
  opt.interrupt = context.interrupt;
  opt.progress = print_progress_line;
  const auto outcome = campaign::run_sweep(opt);
  if (opt.emit_slurm) {
    fmt::print("{} -> submit from {}: sbatch sweep.slurm\n", (outcome.out / "sweep.slurm").string(), outcome.out.string());
    return 0;
  }
  fmt::print("sweep: {} -> {}\n", outcome.record["status"].get<std::string>(), (outcome.out / "sweep.json").string());
  if (outcome.comparison) {
    print_hypothesis_checks(outcome.comparison->hypotheses);
    fmt::print("\n-> {} (iwb report {})\n", (outcome.out / "compare" / "hypotheses.md").string(),
               (outcome.out / "compare").string());
  }
  return outcome.complete() ? 0 : 1;
}

}  // namespace

void add_sweep_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<SweepCommand>();
  auto* sweep = app.add_subcommand(
      "sweep",
      "Run a campaign: the cartesian product of the axes of a sweep file (schema and example: "
      "data/sweeps/README.md) over a base scene, each job a `dem run` in DIR/runs/<job> with a readable "
      "name (rn0.5_d2_cnl_s1). Every job's scene is validated first; a bad value refuses the whole sweep. "
      "At most --jobs run at once with --np ranks each; run it again to continue: complete runs of the same "
      "scene are reused, stopped ones resumed. DIR/sweep.json tracks every job; Ctrl-C stops cleanly. When the "
      "sweep names a comparison, the hypothesis checks of `compare --runs` follow into DIR/compare "
      "(then: iwb report DIR/compare). --emit slurm writes DIR/sweep.slurm (a job array) instead of running.");
  auto& opt = o->options;
  sweep->add_option("sweep", o->sweep_file, "sweep TOML file")->required()->check(input_file());
  sweep->add_option("--jobs,-j", opt.jobs, "jobs at once on this machine (jobs x np should not exceed the cores)")->check(whole_in(1, kMaxProcesses))->capture_default_str();
  sweep->add_option("--np,--threads", opt.processes, "MPI ranks (LIGGGHTS) or threads (YADE) per job")->check(whole_in(1, kMaxProcesses))->capture_default_str();
  sweep->add_option("--emit", o->emit, "write a batch script instead of running: slurm")->check(CLI::IsMember({"slurm"}));
  sweep->add_option("--out,-o", o->out, "campaign directory (default runs/sweep-<sweep file stem>)")->check(output_directory());
  sweep->add_option("--stop-after", opt.stop_after, "stop cleanly once N jobs have ended (running ones are interrupted); run again to continue")->check(whole_in(1, 1000000));
  commands.add(sweep, [o](const CommandContext& c) { return run_sweep(*o, c); });
}

}  // namespace iwb::app
