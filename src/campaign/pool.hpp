#pragma once
// Runs a campaign's jobs on this machine: at most `jobs` at once, each a run_scene with
// `processes` MPI ranks / threads in DIR/runs/<job>. Complete runs of the same scene are reused,
// stopped ones resumed (job_start.hpp). An interrupt (or `stop_after` finished jobs) stops the
// pool cleanly: running jobs are interrupted through run_scene, so their manifests say
// "interrupted at stage ...", and no further job starts. DIR/sweep.json is rewritten atomically
// whenever a job starts or ends.
#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "campaign/jobs.hpp"

namespace iwb::campaign {

struct PoolOptions {
  std::filesystem::path out;
  int jobs = 1;        // at once
  int processes = 1;   // per job
  int stop_after = 0;  // stop cleanly once this many jobs have ended in this invocation (0: never)
  std::string command_line;
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(const std::string&)> progress;  // one line at a time, no newline
};

// Returns sweep.json as written last: "status" is "complete", "interrupted" or
// "finished: N of M failed"; each job has its status, how it started and its wall time.
nlohmann::json run_jobs(const SweepSpec& spec, const std::vector<Job>& jobs,
                        const PoolOptions& options);

}  // namespace iwb::campaign
