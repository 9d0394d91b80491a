#pragma once
// `iwb sweep`: a campaign of DEM runs from a sweep file (data/sweeps/README.md). Loads and expands
// the sweep (every job's scene validated before anything runs), writes DIR/scenes/<job>.toml, then
// either emits a Slurm array (DIR/sweep.slurm) or runs the jobs, here (pool.hpp) or on Slurm
// (slurm_executor.hpp), and, when the sweep names a comparison, the hypothesis checks of
// `iwb compare --runs` over the complete runs into DIR/compare.
#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "campaign/slurm.hpp"
#include "comparison/compare/run_set.hpp"

namespace iwb::campaign {

struct SweepOptions {
  std::filesystem::path sweep_file;
  std::filesystem::path out;  // empty: runs/sweep-<sweep file stem>
  int jobs = 1;
  int processes = 1;
  bool emit_slurm = false;
  bool on_slurm = false;       // --executor slurm
  SlurmOptions slurm;          // partition, account, memory, prologue; time empty: the sweep file's
  double poll_seconds = 10.0;  // --executor slurm: how often squeue is asked
  int stop_after = 0;
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const std::string&)> progress;
};

struct SweepOutcome {
  std::filesystem::path out;
  nlohmann::json record;  // sweep.json (empty when only a Slurm script was emitted)
  std::optional<comparison::RunSetOutcome> comparison;
  bool complete() const { return record.value("status", "") == "complete"; }
};

SweepOutcome run_sweep(const SweepOptions& options);

std::filesystem::path default_out(const std::filesystem::path& sweep_file);

}  // namespace iwb::campaign
