#pragma once
// How a job starts given what its run directory already holds, so that a campaign run again
// continues where it stopped: the same rule as `iwb dem crosscheck` (a complete run of the same
// scene sha256 is reused), plus run_scene's --resume for a run that stopped part-way.
#include <filesystem>
#include <string>

namespace iwb::campaign {

enum class JobStart {
  kSkip,    // complete, same scene: nothing to do
  kResume,  // same scene, failed / interrupted / killed: continue from its last finished stage
  kFresh,   // nothing there, or another scene (the sweep changed): start afresh, replacing it
};

JobStart how_to_start(const std::filesystem::path& run_dir, const std::string& scene_sha256);

const char* to_string(JobStart s);

}  // namespace iwb::campaign
