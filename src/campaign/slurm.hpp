#pragma once
// A campaign as a Slurm job array: one array task per job, each running
// `iwb dem run scenes/<job>.toml --engine E --np R --out runs/<job>` from the campaign directory.
// `iwb sweep --emit slurm` writes it for the user to submit; `--executor slurm` submits it itself
// (slurm_executor.hpp). A job's start flag (--resume, --force) is decided when it is submitted;
// without one, a task that finds a manifest of its own (Slurm requeued it) resumes.
#include <string>
#include <vector>

#include "campaign/jobs.hpp"

namespace iwb::campaign {

struct SlurmOptions {
  std::string name;       // the Slurm job name
  int processes = 1;      // --ntasks of each array task: MPI ranks (LIGGGHTS) or threads (YADE)
  std::string time;       // --time of each array task
  std::string partition;  // --partition; empty: the cluster's default
  std::string account;    // --account; empty: the user's default
  std::string memory;     // --mem of each array task (Slurm's size: 4000, 4G); empty: the default
  std::vector<std::string> prologue;  // shell lines before the job runs (module load ...)
  std::string iwb = "iwb";            // the iwb binary the tasks run (IWB in the environment wins)
};

// Whether `text` is one of Slurm's --time formats: minutes, minutes:seconds,
// hours:minutes:seconds, days-hours, days-hours:minutes, days-hours:minutes:seconds (minutes and
// seconds below 60, hours below 24 after days). Anything else would reach #SBATCH as it is.
bool is_slurm_time(const std::string& text);

// InputError naming the option (--partition, --account, --mem, --time, --prologue) whose value
// Slurm would refuse or misread, before anything is written or submitted.
void check_slurm_options(const SlurmOptions& options);

// Per job, the flag its `dem run` gets ("--resume", "--force", or "" for: resume if a manifest is
// there when the task starts).
using StartFlags = std::vector<std::string>;

// The script's text. Submit it from the campaign directory: paths in it are relative to it. Its
// array covers every job; `sbatch --array=LIST` submits a subset.
std::string slurm_script(const std::vector<Job>& jobs, const SlurmOptions& options,
                         const StartFlags& flags = {});

// Where array task `index` of Slurm job `job_id` writes its output, relative to the campaign
// directory.
std::string task_log(std::size_t index, const std::string& job_id);

}  // namespace iwb::campaign
