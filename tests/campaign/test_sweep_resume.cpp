// A real campaign (LIGGGHTS, three tiny jobs, two at once) stopped when its first job ends and
// run again: only the unfinished jobs run the second time.
#include <catch2/catch.hpp>
#include <filesystem>

#include "campaign/sweep.hpp"
#include "support/sweep_fixtures.hpp"
#include "io/run_directory.hpp"

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

TEST_CASE("a campaign stopped after its first job and run again re-runs only the unfinished jobs", "[campaign][dem]") {
  const auto out = test::campaign_dir("resume");
  // u0.1 and u0.4 start together; u0.1 shears a quarter as far, so it ends first and the stop
  // finds u0.4 shearing and u0.2 not started
  auto opt = test::sweep_options("data/sweeps/tiny.toml", out);
  opt.jobs = 2;
  opt.stop_after = 1;
  const auto first = campaign::run_sweep(opt);
  REQUIRE(first.record["status"] == "interrupted");
  REQUIRE(job_record(first.record, "u0.1")["status"] == "complete");
  const json done = manifest(out, "u0.1");
  const json stopped = manifest(out, "u0.4");
  CHECK_THAT(stopped["status"].get<std::string>(), Catch::StartsWith("interrupted at stage"));
  CHECK(job_record(first.record, "u0.2")["status"] == "pending");
  CHECK_FALSE(fs::exists(out / "runs" / "u0.2"));
  CHECK(json::parse(io::read_file(out / "sweep.json")) == first.record);

  opt.stop_after = 0;
  const auto second = campaign::run_sweep(opt);
  REQUIRE(second.record["status"] == "complete");
  // the complete job was reused as it was: same manifest, same timestamps, never resumed
  CHECK(manifest(out, "u0.1") == done);
  CHECK(job_record(second.record, "u0.1")["start"] == "reused");
  // the interrupted one continued from its last finished stage, the pending one started afresh
  const json resumed = manifest(out, "u0.4");
  CHECK(resumed["status"] == "complete");
  CHECK(resumed["started"] == stopped["started"]);
  CHECK(resumed["resumed"].size() == 1);
  CHECK(job_record(second.record, "u0.4")["start"] == "resumed");
  if (stopped["stages"].contains("consolidate") && stopped["stages"]["consolidate"]["status"] == "done")
    CHECK(resumed["stages"]["consolidate"] == stopped["stages"]["consolidate"]);  // not run again
  CHECK(manifest(out, "u0.2")["status"] == "complete");
  CHECK(job_record(second.record, "u0.2")["start"] == "fresh");
  for (const std::string job : {"u0.1", "u0.4", "u0.2"}) CHECK(fs::exists(out / "runs" / job / "summary.json"));
}
