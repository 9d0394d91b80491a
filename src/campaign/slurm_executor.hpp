#pragma once
// `iwb sweep --executor slurm`: the campaign submitted to Slurm as a job array (slurm.hpp), watched
// with squeue until every task has ended, each task that ended without a complete run resubmitted
// once (it resumes from its run directory), and its outcome gathered into sweep.json as the local
// pool keeps it (sweep_record.hpp). The run directories are the truth: a task's state in Slurm says
// only whether it is still queued or running. Stopping the watcher (Ctrl-C) leaves the tasks to
// Slurm; the same command again adopts the tasks still queued or running (their job IDs are in
// sweep.json) instead of submitting them twice.
#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "campaign/jobs.hpp"
#include "campaign/slurm.hpp"

namespace iwb::campaign {

struct SlurmExecutorOptions {
  std::filesystem::path out;
  SlurmOptions slurm;
  double poll_seconds = 10.0;  // how often squeue is asked
  int resubmits = 1;           // per job whose task ended without a complete run
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const std::string&)> progress;  // one line at a time, no newline
};

// InputError, nothing submitted or written: sbatch or squeue not on PATH, or the cluster's own
// sbatch --test-only refusing the script (an unknown partition or account, a time above the
// partition's limit).
void check_slurm_submission(const std::vector<Job>& jobs, const SlurmOptions& options);

// sweep.json as written last; "status" as the local pool's.
nlohmann::json run_jobs_on_slurm(const SweepSpec& spec, const std::vector<Job>& jobs,
                                 const SlurmExecutorOptions& options);

}  // namespace iwb::campaign
