#pragma once
// sweep.json, the campaign's record, as both executors keep it (the local pool, pool.hpp, and
// Slurm, slurm_executor.hpp): the sweep and every job with its values, scene sha256, status, how it
// started and its wall time; and the counts and status line read off it.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "campaign/jobs.hpp"

namespace iwb::campaign {

// How often a campaign repeats its progress line while nothing changes.
inline constexpr double kProgressEverySeconds = 15.0;

// The sha256 that decides reuse of a job's run (dem::scene_sha256: its text and any wall file it
// names).
std::string job_scene_sha256(const Job& job, const std::filesystem::path& out);

// The engine's own time in an earlier run, for reused jobs.
double recorded_seconds(const std::filesystem::path& run_dir);

// Every job "pending"; `executor` ("local" or "slurm") and its settings.
nlohmann::json initial_record(const SweepSpec& spec, const std::vector<Job>& jobs,
                              const std::filesystem::path& out, const std::string& command_line,
                              const nlohmann::json& executor);

// A job found complete with the same scene before anything ran.
void mark_reused(nlohmann::json& job, const std::filesystem::path& run_dir);

struct JobCounts {
  int complete = 0, reused = 0, running = 0, failed = 0, pending = 0;
};
// "running" counts queued and running alike; an interrupted job is still to do.
JobCounts count_jobs(const nlohmann::json& record);

// "complete", "interrupted" (stopped with jobs to do) or "finished: N of M failed".
std::string overall_status(const nlohmann::json& record, bool stopped);

void write_record(nlohmann::json& record, const std::filesystem::path& out);

}  // namespace iwb::campaign
