#pragma once
// `iwb sweep --emit slurm`: the same campaign as a Slurm job array, one array task per job, each
// running `iwb dem run scenes/<job>.toml --engine E --np R --out runs/<job>` (with --resume once
// the job's run directory holds a manifest, so a requeued or resubmitted task continues).
#include <string>
#include <vector>

#include "campaign/jobs.hpp"

namespace iwb::campaign {

struct SlurmOptions {
  std::string name;  // the Slurm job name
  int processes = 1;  // --ntasks of each array task: MPI ranks (LIGGGHTS) or threads (YADE)
  std::string time;   // --time of each array task
};

// Whether `text` is one of Slurm's --time formats: minutes, minutes:seconds,
// hours:minutes:seconds, days-hours, days-hours:minutes, days-hours:minutes:seconds (minutes and
// seconds below 60, hours below 24 after days). Anything else would reach #SBATCH as it is.
bool is_slurm_time(const std::string& text);

// The script's text. Submit it from the campaign directory: paths in it are relative to it.
std::string slurm_script(const std::vector<Job>& jobs, const SlurmOptions& options);

}  // namespace iwb::campaign
