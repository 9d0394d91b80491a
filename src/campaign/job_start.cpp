#include "campaign/job_start.hpp"

#include <nlohmann/json.hpp>

#include "io/run_directory.hpp"

namespace iwb::campaign {

JobStart how_to_start(const std::filesystem::path& dir, const std::string& sha) {
  const auto file = dir / "manifest.json";
  if (!std::filesystem::exists(file)) return JobStart::kFresh;
  nlohmann::json m;
  try {
    m = nlohmann::json::parse(io::read_file(file));
  } catch (const nlohmann::json::parse_error&) {
    return JobStart::kFresh;  // manifests are written atomically: a broken one is not ours to
                              // resume
  }
  if (m.value("/scene/sha256"_json_pointer, std::string()) != sha) return JobStart::kFresh;
  if (m.value("status", "") == "complete") return JobStart::kSkip;
  return JobStart::kResume;  // run_scene re-runs every stage not marked done
}

const char* to_string(JobStart s) {
  switch (s) {
    case JobStart::kSkip:
      return "reused";
    case JobStart::kResume:
      return "resumed";
    case JobStart::kFresh:
      return "fresh";
  }
  return "?";
}

}  // namespace iwb::campaign
