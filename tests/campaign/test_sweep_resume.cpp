// A real campaign (LIGGGHTS, three tiny jobs, two at once) stopped when its first job ends and
// run again: only the unfinished jobs run the second time.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>

#include "campaign/sweep.hpp"
#include "io/run_directory.hpp"
#include "support/sweep_fixtures.hpp"

using namespace iwb;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {
json manifest(const fs::path& out, const std::string& job) {
  return json::parse(io::read_file(out / "runs" / job / "manifest.json"));
}
json job_record(const json& sweep, const std::string& name) {
  for (const auto& j : sweep["jobs"])
    if (j["name"] == name) return j;
  FAIL("no job " << name << " in sweep.json");
  return {};
}
}  // namespace

TEST_CASE("a campaign stopped after its first job and run again re-runs only the unfinished jobs",
          "[campaign][dem]") {
  const auto out = test::campaign_dir("resume");
  // data/sweeps/tiny.toml: u0.05 and u10 start together with the same consolidation; u10 then
  // shears 200 times as far (seconds more), so u0.05 ends first and the stop finds u10 shearing
  // and u0.1 not started
  auto opt = test::sweep_options("data/sweeps/tiny.toml", out);
  opt.jobs = 2;
  opt.stop_after = 1;
  std::vector<std::string> lines;
  opt.progress = [&lines](const std::string& line) { lines.push_back(line); };
  const auto first = campaign::run_sweep(opt);
  // when u0.05 ends, u10 (started with it) is running: the sweep's line carries u10's own
  // progress (its stage, how far, its ETA), since until a job ends the sweep has no ETA of its own;
  // once u10 has stopped, its line is gone
  const auto ended = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.rfind("u0.05: complete; sweep:", 0) == 0;
  });
  REQUIRE(ended != lines.end());
  CHECK_THAT(*ended, Catch::Contains("; u10: "));
  CHECK_THAT(lines.back(), !Catch::Contains("u10: "));
  REQUIRE(first.record["status"] == "interrupted");
  REQUIRE(job_record(first.record, "u0.05")["status"] == "complete");
  const json done = manifest(out, "u0.05");
  const json stopped = manifest(out, "u10");
  CHECK(stopped["status"] == "interrupted at stage shear");
  CHECK(job_record(first.record, "u0.1")["status"] == "pending");
  CHECK_FALSE(fs::exists(out / "runs" / "u0.1"));
  CHECK(json::parse(io::read_file(out / "sweep.json")) == first.record);

  opt.stop_after = 0;
  const auto second = campaign::run_sweep(opt);
  REQUIRE(second.record["status"] == "complete");
  // the complete job was reused as it was: same manifest, same timestamps, never resumed
  CHECK(manifest(out, "u0.05") == done);
  CHECK(job_record(second.record, "u0.05")["start"] == "reused");
  // the interrupted one continued from its last finished stage, the pending one started afresh
  const json resumed = manifest(out, "u10");
  CHECK(resumed["status"] == "complete");
  CHECK(resumed["started"] == stopped["started"]);
  CHECK(resumed["resumed"].size() == 1);
  CHECK(job_record(second.record, "u10")["start"] == "resumed");
  CHECK(resumed["stages"]["consolidate"] == stopped["stages"]["consolidate"]);  // not run again
  CHECK(manifest(out, "u0.1")["status"] == "complete");
  CHECK(job_record(second.record, "u0.1")["start"] == "fresh");
  for (const std::string job : {"u0.05", "u10", "u0.1"})
    CHECK(fs::exists(out / "runs" / job / "summary.json"));
}
