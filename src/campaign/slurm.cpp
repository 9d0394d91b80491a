#include "campaign/slurm.hpp"

#include <fmt/core.h>

#include <regex>

#include "common/errors.hpp"

namespace iwb::campaign {

bool is_slurm_time(const std::string& text) {
  static const std::regex formats(R"((\d+)|(\d+):([0-5]?\d)|(\d+):([0-5]?\d):([0-5]?\d)|)"
                                  R"((\d+)-([01]?\d|2[0-3])(:[0-5]?\d){0,2})");
  return std::regex_match(text, formats);
}

void check_slurm_options(const SlurmOptions& o) {
  // Slurm's names: letters, digits and ._- (a partition list is comma-separated)
  static const std::regex name(R"([A-Za-z0-9_.\-]+(,[A-Za-z0-9_.\-]+)*)"), size(R"(\d+[KMGT]?)");
  const auto refuse = [](const std::string& option, const std::string& value,
                         const std::string& why) {
    return InputError(fmt::format("{} '{}': {}; nothing was submitted", option, value, why));
  };
  if (!o.partition.empty() && !std::regex_match(o.partition, name))
    throw refuse("--partition", o.partition,
                 "not a partition name (letters, digits, '._-', comma-separated)");
  if (!o.account.empty() && !std::regex_match(o.account, name))
    throw refuse("--account", o.account, "not an account name (letters, digits, '._-')");
  if (!o.memory.empty() && !std::regex_match(o.memory, size))
    throw refuse("--mem", o.memory,
                 "not a Slurm memory size (a whole number of megabytes, or with K, M, G or T: 4G)");
  if (!is_slurm_time(o.time))
    throw refuse(
        "--time", o.time,
        "not one of Slurm's --time formats (MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS)");
  for (const auto& line : o.prologue)
    if (line.find('\n') != std::string::npos || line.rfind("#SBATCH", 0) == 0)
      throw refuse("--prologue", line,
                   "one shell line each, and not an #SBATCH line (use the options)");
}

std::string task_log(std::size_t index, const std::string& job_id) {
  return fmt::format("logs/{}-{}.out", index, job_id);
}

namespace {

// A word the shell takes as it is: bare when it holds only safe characters (the usual job and
// path names), else single-quoted, so that no name from a sweep file runs as shell.
std::string shell_word(const std::string& s) {
  if (!s.empty() &&
      s.find_first_not_of(
          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._/+=:,@%-") ==
          std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string sbatch_lines(const SlurmOptions& o, std::size_t jobs) {
  std::string s = fmt::format(
      "#SBATCH --job-name={}\n#SBATCH --array=0-{}\n#SBATCH --ntasks={}\n#SBATCH --time={}\n"
      "#SBATCH --output=logs/%a-%A.out\n",
      o.name, jobs - 1, o.processes, o.time);
  if (!o.partition.empty()) s += fmt::format("#SBATCH --partition={}\n", o.partition);
  if (!o.account.empty()) s += fmt::format("#SBATCH --account={}\n", o.account);
  if (!o.memory.empty()) s += fmt::format("#SBATCH --mem={}\n", o.memory);
  return s;
}

}  // namespace

std::string slurm_script(const std::vector<Job>& jobs, const SlurmOptions& opt,
                         const StartFlags& flags) {
  std::string s = fmt::format(
      "#!/bin/bash\n# {} jobs of an iwb sweep; submit from this directory: sbatch sweep.slurm\n",
      jobs.size());
  s += sbatch_lines(opt, jobs.size());
  s += "set -euo pipefail\n";
  for (const auto& line : opt.prologue) s += line + "\n";
  s += fmt::format(
      "IWB=${{IWB:-{}}}  # the iwb binary on the cluster\n"
      "# `dem run --resume` needs an earlier run: a first attempt starts afresh, a requeued one "
      "resumes\n"
      "resume() {{ [ -f \"$1/manifest.json\" ] && echo --resume || true; }}\n"
      "case \"$SLURM_ARRAY_TASK_ID\" in\n",
      shell_word(opt.iwb));
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const auto& j = jobs[i];
    const std::string flag = i < flags.size() && !flags[i].empty()
                                 ? flags[i]
                                 : fmt::format("$(resume {})", shell_word(run_path(j)));
    s += fmt::format(
        "  {}) \"$IWB\" dem run {} --engine {} --np {} --out {} --consolidated consolidated {} "
        ";;\n",
        i, shell_word(scene_path(j)), j.engine, opt.processes, shell_word(run_path(j)), flag);
  }
  s += "  *) echo \"no job for array index $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;\nesac\n";
  return s;
}

}  // namespace iwb::campaign
