#include "campaign/slurm.hpp"

#include <fmt/core.h>
#include <regex>

namespace iwb::campaign {

bool is_slurm_time(const std::string& text) {
  static const std::regex formats(
      R"((\d+)|(\d+):([0-5]?\d)|(\d+):([0-5]?\d):([0-5]?\d)|)"
      R"((\d+)-([01]?\d|2[0-3])(:[0-5]?\d){0,2})");
  return std::regex_match(text, formats);
}

std::string slurm_script(const std::vector<Job>& jobs, const SlurmOptions& opt) {
  std::string s = fmt::format(
      "#!/bin/bash\n"
      "# {} jobs of an iwb sweep; submit from this directory: sbatch sweep.slurm\n"
      "#SBATCH --job-name={}\n"
      "#SBATCH --array=0-{}\n"
      "#SBATCH --ntasks={}\n"
      "#SBATCH --time={}\n"
      "#SBATCH --output=logs/%x_%a.out\n"
      "set -euo pipefail\n"
      "IWB=${{IWB:-iwb}}  # the iwb binary on the cluster\n"
      "# `dem run --resume` needs an earlier run: a first attempt starts afresh, a requeued one resumes\n"
      "resume() {{ [ -f \"$1/manifest.json\" ] && echo --resume || true; }}\n"
      "case \"$SLURM_ARRAY_TASK_ID\" in\n",
      jobs.size(), opt.name, jobs.size() - 1, opt.processes, opt.time);
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const auto& j = jobs[i];
    s += fmt::format("  {}) \"$IWB\" dem run {} --engine {} --np {} --out {} --consolidated consolidated $(resume {}) ;;\n",
                     i, scene_path(j), j.engine, opt.processes, run_path(j), run_path(j));
  }
  s += "  *) echo \"no job for array index $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;\nesac\n";
  return s;
}

}  // namespace iwb::campaign
