#include "campaign/sweep.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

#include "campaign/jobs.hpp"
#include "campaign/pool.hpp"
#include "campaign/slurm.hpp"
#include "campaign/slurm_executor.hpp"
#include "io/directory_lock.hpp"
#include "io/run_directory.hpp"

namespace iwb::campaign {

namespace fs = std::filesystem;

fs::path default_out(const fs::path& sweep_file) {
  return fs::path("runs") / ("sweep-" + sweep_file.stem().string());
}

namespace {

void write_scenes(const std::vector<Job>& jobs, const fs::path& out) {
  fs::create_directories(out / "scenes");
  for (const auto& job : jobs) io::write_atomically(out / scene_path(job), job.scene_text);
}

// The hypothesis checks over the runs that completed; failed runs are left out, not compared.
comparison::RunSetOutcome compare_complete_runs(const Comparison& c, const nlohmann::json& record,
                                                const SweepOptions& opt, const fs::path& out) {
  comparison::RunSetOptions set;
  set.model = c.model, set.params = c.params.string(), set.out = out / "compare";
  set.allow_partial = false, set.force = true, set.command_line = opt.command_line;
  // force: DIR/compare belongs to the campaign; a re-run job's comparison is stale, not precious.
  for (const auto& j : record["jobs"])
    if (j["status"] == "complete") set.dem_dirs.push_back(out / j["run"].get<std::string>());
  return comparison::run_hypothesis_set(set);
}

// The Slurm settings: the command line's, the time from the sweep file unless given, the job named
// after the sweep; the tasks of --executor slurm run this very binary.
SlurmOptions slurm_options(const SweepOptions& opt, const SweepSpec& spec) {
  SlurmOptions s = opt.slurm;
  s.name = "iwb-" + opt.sweep_file.stem().string();
  for (char& c :
       s.name)  // an #SBATCH value ends at a space: the job name keeps safe characters only
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  s.processes = opt.processes;
  if (s.time.empty()) s.time = spec.slurm_time;
  if (opt.on_slurm) s.iwb = fs::read_symlink("/proc/self/exe").string();
  return s;
}

nlohmann::json run_jobs_somewhere(const SweepSpec& spec, const std::vector<Job>& jobs,
                                  const SlurmOptions& slurm, const SweepOptions& opt,
                                  const fs::path& out) {
  if (!opt.on_slurm)
    return run_jobs(spec, jobs,
                    {out, opt.jobs, opt.processes, opt.stop_after, opt.command_line, opt.interrupt,
                     opt.progress});
  return run_jobs_on_slurm(spec, jobs,
                           {fs::absolute(out), slurm, opt.poll_seconds, 1, opt.command_line,
                            opt.interrupt, opt.progress});
}

}  // namespace

SweepOutcome run_sweep(const SweepOptions& opt) {
  const SweepSpec spec = load_sweep(opt.sweep_file);
  const std::vector<Job> jobs = expand_jobs(spec);  // refuses the sweep before anything is written
  const SlurmOptions slurm = slurm_options(opt, spec);
  if (opt.emit_slurm) check_slurm_options(slurm);
  if (opt.on_slurm)
    check_slurm_submission(jobs, slurm);  // the cluster's judgement too, nothing queued
  SweepOutcome outcome{opt.out.empty() ? default_out(opt.sweep_file) : opt.out, {}, std::nullopt};
  const io::OutputKind kind{"sweep", "sweep.json"};        // a campaign resumes where it stopped
  io::require_output_directory(outcome.out, kind, false);  // before the lock touches it
  const auto lock =
      io::DirectoryLock::take(outcome.out, opt.command_line);  // each job locks its own run
  io::claim_output_directory(outcome.out, kind, false);
  write_scenes(jobs, outcome.out);
  if (opt.emit_slurm) {
    fs::create_directories(outcome.out / "logs");  // Slurm does not create the --output folder
    io::write_atomically(outcome.out / "sweep.slurm", slurm_script(jobs, slurm));
    return outcome;
  }
  outcome.record = run_jobs_somewhere(spec, jobs, slurm, opt, outcome.out);
  const bool stopped = outcome.record["status"] == "interrupted";
  const bool any_complete =
      std::any_of(outcome.record["jobs"].begin(), outcome.record["jobs"].end(),
                  [](const auto& j) { return j["status"] == "complete"; });
  if (spec.compare && !stopped && any_complete) {
    if (opt.progress)
      opt.progress(fmt::format("comparing the complete runs with {} -> {}", spec.compare->model,
                               (outcome.out / "compare").string()));
    outcome.comparison = compare_complete_runs(*spec.compare, outcome.record, opt, outcome.out);
    outcome.record["compare"] = {{"dir", "compare"},
                                 {"model", spec.compare->model},
                                 {"params", spec.compare->params.string()}};
    io::write_atomically(outcome.out / "sweep.json", outcome.record.dump(2) + "\n");
  }
  return outcome;
}

}  // namespace iwb::campaign
