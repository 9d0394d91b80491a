#include "campaign/sweep_record.hpp"

#include <fmt/core.h>

#include "campaign/job_start.hpp"
#include "dem/scene/scene.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::campaign {

namespace fs = std::filesystem;
using nlohmann::json;

std::string job_scene_sha256(const Job& job, const fs::path& out) {
  return dem::scene_sha256(dem::parse_scene(job.scene_text, (out / scene_path(job)).string()),
                           job.scene_text);
}

double recorded_seconds(const fs::path& dir) {
  const auto m = io::read_json_file(dir / "manifest.json");
  double s = 0.0;
  for (const auto& [name, stage] : m["stages"].items()) s += stage.value("wall_seconds", 0.0);
  return s;
}

json initial_record(const SweepSpec& spec, const std::vector<Job>& jobs, const fs::path& out,
                    const std::string& command_line, const json& executor) {
  json r = {{"kind", "dem-sweep"},
            {"sweep", spec.file.string()},
            {"sweep_sha256", io::sha256_hex(spec.text)},
            {"scene", spec.scene_file.string()},
            {"command_line", command_line},
            {"started", io::utc_timestamp()},
            {"status", "running"},
            {"jobs", json::array()}};
  r.update(executor);
  for (const auto& job : jobs) {
    json values = json::object();
    for (const auto& [key, value] : job.values) values[key] = io::to_toml(value);
    r["jobs"].push_back({{"name", job.name},
                         {"engine", job.engine},
                         {"values", values},
                         {"scene", scene_path(job)},
                         {"run", run_path(job)},
                         {"scene_sha256", job_scene_sha256(job, out)},
                         {"status", "pending"}});
  }
  return r;
}

void mark_reused(json& job, const fs::path& run_dir) {
  job["status"] = "complete";
  job["start"] = to_string(JobStart::kSkip);
  job["wall_seconds"] = recorded_seconds(run_dir);
}

JobCounts count_jobs(const json& record) {
  JobCounts c;
  for (const auto& j : record["jobs"]) {
    const std::string s = j["status"];
    if (s == "complete") {
      ++c.complete;
      if (j.value("start", "") == "reused") ++c.reused;
    } else if (s == "running" || s == "queued") {
      ++c.running;
    } else if (s == "pending" || s.rfind("interrupted", 0) == 0) {
      ++c.pending;
    } else {
      ++c.failed;
    }
  }
  return c;
}

std::string overall_status(const json& record, bool stopped) {
  const JobCounts c = count_jobs(record);
  if (c.complete == int(record["jobs"].size())) return "complete";
  if (stopped && (c.pending > 0 || c.running > 0)) return "interrupted";
  return fmt::format("finished: {} of {} failed", c.failed, record["jobs"].size());
}

void write_record(json& record, const fs::path& out) {
  record["updated"] = io::utc_timestamp();
  io::write_atomically(out / "sweep.json", record.dump(2) + "\n");
}

}  // namespace iwb::campaign
