// `iwb sweep SWEEP.toml`: a campaign of DEM runs, then its verdicts (campaign/sweep.hpp).
#include "campaign/sweep.hpp"

#include <fmt/core.h>

#include <fstream>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"
#include "app/progress.hpp"
#include "common/errors.hpp"

namespace iwb::app {

namespace {

struct SweepCommand {
  campaign::SweepOptions options;
  std::string sweep_file, out, emit, executor = "local";
};

// The Slurm options mean nothing to a local run, and --jobs and --stop-after nothing to Slurm
// (it decides how many tasks run at once): refused rather than ignored.
void require_slurm_for_slurm_options(const SweepCommand& o) {
  const auto& s = o.options.slurm;
  // --emit slurm stops at the script: the submission asked for would silently not happen
  if (o.emit == "slurm" && o.executor == "slurm")
    throw InputError(
        "--emit slurm with --executor slurm: --emit slurm writes the job array for you to submit, "
        "--executor slurm submits it; give one");
  if (o.executor == "slurm")
    for (const auto& [option, given] :
         {std::pair{"--jobs", o.options.jobs != 1}, {"--stop-after", o.options.stop_after != 0}})
      if (given)
        throw InputError(
            fmt::format("{} is for a local run: with --executor slurm, Slurm decides how many "
                        "tasks run at once",
                        option));
  if (o.executor == "slurm" || o.emit == "slurm") return;
  if (o.options.poll_seconds != campaign::SweepOptions{}.poll_seconds)
    throw InputError("--poll is a Slurm option: it needs --executor slurm");
  for (const auto& [option, given] : {std::pair{"--partition", !s.partition.empty()},
                                      {"--account", !s.account.empty()},
                                      {"--time", !s.time.empty()},
                                      {"--mem", !s.memory.empty()},
                                      {"--prologue", !s.prologue.empty()}})
    if (given)
      throw InputError(
          fmt::format("{} is a Slurm option: it needs --executor slurm or --emit slurm", option));
}

// The tasks' logs of the jobs that failed on Slurm: the last lines of each, so the reason is seen
// here.
void print_failed_task_logs(const nlohmann::json& record, const std::filesystem::path& out) {
  for (const auto& j : record["jobs"]) {
    const std::string status = j["status"];
    if (!j.contains("log") || status == "complete" || status == "queued" || status == "running")
      continue;
    fmt::print("{}: {}\n  log {}:\n", j["name"].get<std::string>(), j["status"].get<std::string>(),
               (out / j["log"].get<std::string>()).string());
    std::vector<std::string> lines;
    std::ifstream log(out / j["log"].get<std::string>());
    for (std::string l; std::getline(log, l);) lines.push_back(l);
    for (std::size_t i = lines.size() > 8 ? lines.size() - 8 : 0; i < lines.size(); ++i)
      fmt::print("    {}\n", lines[i]);
  }
}

// The campaign, then its verdicts when it names a comparison.
int run_sweep(const SweepCommand& o, const CommandContext& context) {
  auto opt = o.options;
  opt.sweep_file = o.sweep_file;
  opt.out = o.out;
  opt.emit_slurm = o.emit == "slurm";
  opt.on_slurm = o.executor == "slurm";
  require_slurm_for_slurm_options(o);
  opt.command_line = context.command_line;
  opt.interrupt = context.interrupt;
  opt.progress = print_progress_line;
  const auto outcome = campaign::run_sweep(opt);
  if (opt.emit_slurm) {
    fmt::print("{} -> submit from {}: sbatch sweep.slurm\n", (outcome.out / "sweep.slurm").string(),
               outcome.out.string());
    return 0;
  }
  if (opt.on_slurm) print_failed_task_logs(outcome.record, outcome.out);
  if (outcome.record.contains("note"))
    fmt::print("{}\n", outcome.record["note"].get<std::string>());
  fmt::print("sweep: {} -> {}\n", outcome.record["status"].get<std::string>(),
             (outcome.out / "sweep.json").string());
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
      "data/sweeps/README.md) over a base scene, each job a `dem run` in DIR/runs/<job> with a "
      "readable "
      "name (rn0.5_d2_cnl_s1). Every job's scene is validated first; a bad value refuses the whole "
      "sweep. "
      "At most --jobs run at once with --np ranks each; run it again to continue: complete runs of "
      "the same "
      "scene are reused, stopped ones resumed. DIR/sweep.json tracks every job; Ctrl-C stops "
      "cleanly. When the "
      "sweep names a comparison, the hypothesis checks of `compare --runs` follow into DIR/compare "
      "(then: iwb report DIR/compare). --emit slurm writes DIR/sweep.slurm (a job array) instead "
      "of running; "
      "--executor slurm submits it to Slurm from this machine (sbatch), watches the tasks "
      "(squeue), resubmits once "
      "each task that ended without a complete run (it resumes), then gathers and compares as "
      "here; each task runs "
      "this iwb with --np ranks (mpirun inside the task). Slurm example: iwb sweep "
      "data/sweeps/tiny.toml "
      "--executor slurm --partition short --time 00:20:00 --mem 2G --prologue 'module load "
      "openmpi' "
      "(data/sweeps/README.md, \"On a cluster\").");
  auto& opt = o->options;
  sweep->add_option("sweep", o->sweep_file, "sweep TOML file")->required()->check(input_file());
  sweep
      ->add_option("--jobs,-j", opt.jobs,
                   "jobs at once on this machine (jobs x np should not exceed the cores)")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  sweep
      ->add_option("--np,--threads", opt.processes,
                   "MPI ranks (LIGGGHTS) or threads (YADE) per job")
      ->check(whole_in(1, kMaxProcesses))
      ->capture_default_str();
  sweep->add_option("--emit", o->emit, "write a batch script instead of running: slurm")
      ->check(CLI::IsMember({"slurm"}));
  sweep
      ->add_option("--executor", o->executor,
                   "where the jobs run: local (this machine, --jobs at once) or slurm (array tasks "
                   "submitted with sbatch)")
      ->check(CLI::IsMember({"local", "slurm"}))
      ->capture_default_str();
  auto& slurm = opt.slurm;
  sweep
      ->add_option("--partition", slurm.partition,
                   "Slurm: the partition of the array tasks (default: the cluster's)")
      ->check(non_empty());
  sweep->add_option("--account", slurm.account, "Slurm: the account charged (default: yours)")
      ->check(non_empty());
  sweep
      ->add_option("--time", slurm.time,
                   "Slurm: wall-clock limit of one task (default: the sweep file's [slurm] time, "
                   "else 01:00:00)")
      ->check(non_empty());
  sweep->add_option("--mem", slurm.memory, "Slurm: memory of one task (4000 = MB, or 4G)")
      ->check(non_empty());
  sweep
      ->add_option("--prologue", slurm.prologue,
                   "Slurm: a shell line each task runs first, e.g. 'module load openmpi'; repeat "
                   "for several")
      ->check(non_empty());
  sweep->add_option("--poll", opt.poll_seconds, "Slurm: seconds between looks at the queue")
      ->check(number_in({1.0, 3600.0}, "s"))
      ->capture_default_str();
  sweep->add_option("--out,-o", o->out, "campaign directory (default runs/sweep-<sweep file stem>)")
      ->check(output_directory());
  sweep
      ->add_option("--stop-after", opt.stop_after,
                   "stop cleanly once N jobs have ended (running ones are interrupted); run again "
                   "to continue")
      ->check(whole_in(1, 1000000));
  commands.add(sweep, [o](const CommandContext& c) { return run_sweep(*o, c); });
}

}  // namespace iwb::app
